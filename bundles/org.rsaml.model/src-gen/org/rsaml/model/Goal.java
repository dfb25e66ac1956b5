/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Goal</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A goal to be achieved by the robot; it can be broken into sub-goals.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Goal#getMission <em>Mission</em>}</li>
 *   <li>{@link org.rsaml.model.Goal#getParentGoal <em>Parent Goal</em>}</li>
 *   <li>{@link org.rsaml.model.Goal#getSubGoals <em>Sub Goals</em>}</li>
 *   <li>{@link org.rsaml.model.Goal#getPriority <em>Priority</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getGoal()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA09_uniqueNames'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA09_uniqueNames='subGoals-&gt;isUnique(normalizedName())'"
 * @generated
 */
public interface Goal extends NamedElement {
	/**
	 * Returns the value of the '<em><b>Mission</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Mission#getGoals <em>Goals</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The mission that contains this goal, for a top-level goal.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Mission</em>' container reference.
	 * @see #setMission(Mission)
	 * @see org.rsaml.model.RsamlPackage#getGoal_Mission()
	 * @see org.rsaml.model.Mission#getGoals
	 * @model opposite="goals"
	 * @generated
	 */
	Mission getMission();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Goal#getMission <em>Mission</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Mission</em>' container reference.
	 * @see #getMission()
	 * @generated
	 */
	void setMission(Mission value);

	/**
	 * Returns the value of the '<em><b>Parent Goal</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Goal#getSubGoals <em>Sub Goals</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The goal this goal is a sub-goal of, for a sub-goal.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Parent Goal</em>' container reference.
	 * @see #setParentGoal(Goal)
	 * @see org.rsaml.model.RsamlPackage#getGoal_ParentGoal()
	 * @see org.rsaml.model.Goal#getSubGoals
	 * @model opposite="subGoals"
	 * @generated
	 */
	Goal getParentGoal();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Goal#getParentGoal <em>Parent Goal</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Parent Goal</em>' container reference.
	 * @see #getParentGoal()
	 * @generated
	 */
	void setParentGoal(Goal value);

	/**
	 * Returns the value of the '<em><b>Sub Goals</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Goal}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Goal#getParentGoal <em>Parent Goal</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The sub-goals that together achieve this goal.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Sub Goals</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getGoal_SubGoals()
	 * @see org.rsaml.model.Goal#getParentGoal
	 * @model opposite="parentGoal" containment="true" keys="name"
	 * @generated
	 */
	EList<Goal> getSubGoals();

	/**
	 * Returns the value of the '<em><b>Priority</b></em>' attribute.
	 * The default value is <code>"0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The goal's priority among its siblings; higher values are pursued first.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Priority</em>' attribute.
	 * @see #setPriority(int)
	 * @see org.rsaml.model.RsamlPackage#getGoal_Priority()
	 * @model default="0"
	 * @generated
	 */
	int getPriority();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Goal#getPriority <em>Priority</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Priority</em>' attribute.
	 * @see #getPriority()
	 * @generated
	 */
	void setPriority(int value);

} // Goal
