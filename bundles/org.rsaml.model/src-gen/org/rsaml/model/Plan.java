/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Plan</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A sequence of activities that performs a mission and achieves some of its goals.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Plan#getMission <em>Mission</em>}</li>
 *   <li>{@link org.rsaml.model.Plan#getActivities <em>Activities</em>}</li>
 *   <li>{@link org.rsaml.model.Plan#getAchieves <em>Achieves</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getPlan()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA09_uniqueNames'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA09_uniqueNames='activities-&gt;isUnique(normalizedName())'"
 * @generated
 */
public interface Plan extends NamedElement {
	/**
	 * Returns the value of the '<em><b>Mission</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Mission#getPlans <em>Plans</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The mission this plan carries out.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Mission</em>' container reference.
	 * @see #setMission(Mission)
	 * @see org.rsaml.model.RsamlPackage#getPlan_Mission()
	 * @see org.rsaml.model.Mission#getPlans
	 * @model opposite="plans"
	 * @generated
	 */
	Mission getMission();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Plan#getMission <em>Mission</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Mission</em>' container reference.
	 * @see #getMission()
	 * @generated
	 */
	void setMission(Mission value);

	/**
	 * Returns the value of the '<em><b>Activities</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Activity}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Activity#getPlan <em>Plan</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The plan's activities, in the order they are performed.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Activities</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getPlan_Activities()
	 * @see org.rsaml.model.Activity#getPlan
	 * @model opposite="plan" containment="true" keys="name"
	 * @generated
	 */
	EList<Activity> getActivities();

	/**
	 * Returns the value of the '<em><b>Achieves</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Goal}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The goals this plan achieves when it completes.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Achieves</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getPlan_Achieves()
	 * @model
	 * @generated
	 */
	EList<Goal> getAchieves();

} // Plan
