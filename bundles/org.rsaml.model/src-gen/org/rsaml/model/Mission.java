/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Mission</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * An established set of goals, tasks and paths given to the robot.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Mission#getArchitecture <em>Architecture</em>}</li>
 *   <li>{@link org.rsaml.model.Mission#getGoals <em>Goals</em>}</li>
 *   <li>{@link org.rsaml.model.Mission#getPlans <em>Plans</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getMission()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA09_uniqueNames'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA09_uniqueNames='goals-&gt;isUnique(normalizedName()) and plans-&gt;isUnique(normalizedName())'"
 * @generated
 */
public interface Mission extends NamedElement {
	/**
	 * Returns the value of the '<em><b>Architecture</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Architecture#getMissions <em>Missions</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The architecture that contains this mission.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Architecture</em>' container reference.
	 * @see #setArchitecture(Architecture)
	 * @see org.rsaml.model.RsamlPackage#getMission_Architecture()
	 * @see org.rsaml.model.Architecture#getMissions
	 * @model opposite="missions"
	 * @generated
	 */
	Architecture getArchitecture();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Mission#getArchitecture <em>Architecture</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Architecture</em>' container reference.
	 * @see #getArchitecture()
	 * @generated
	 */
	void setArchitecture(Architecture value);

	/**
	 * Returns the value of the '<em><b>Goals</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Goal}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Goal#getMission <em>Mission</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The top-level goals the mission must achieve.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Goals</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getMission_Goals()
	 * @see org.rsaml.model.Goal#getMission
	 * @model opposite="mission" containment="true" keys="name"
	 * @generated
	 */
	EList<Goal> getGoals();

	/**
	 * Returns the value of the '<em><b>Plans</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Plan}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Plan#getMission <em>Mission</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The plans that can carry the mission out.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Plans</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getMission_Plans()
	 * @see org.rsaml.model.Plan#getMission
	 * @model opposite="mission" containment="true" keys="name"
	 * @generated
	 */
	EList<Plan> getPlans();

} // Mission
