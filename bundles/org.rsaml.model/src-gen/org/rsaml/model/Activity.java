/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Activity</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A task or sequence of tasks of the robot within a plan, carried out by actions of the architecture.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Activity#getPlan <em>Plan</em>}</li>
 *   <li>{@link org.rsaml.model.Activity#getActions <em>Actions</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getActivity()
 * @model
 * @generated
 */
public interface Activity extends RealTimeElement {
	/**
	 * Returns the value of the '<em><b>Plan</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Plan#getActivities <em>Activities</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The plan that contains this activity.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Plan</em>' container reference.
	 * @see #setPlan(Plan)
	 * @see org.rsaml.model.RsamlPackage#getActivity_Plan()
	 * @see org.rsaml.model.Plan#getActivities
	 * @model opposite="activities"
	 * @generated
	 */
	Plan getPlan();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Activity#getPlan <em>Plan</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Plan</em>' container reference.
	 * @see #getPlan()
	 * @generated
	 */
	void setPlan(Plan value);

	/**
	 * Returns the value of the '<em><b>Actions</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Action}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The actions of the architecture that carry the activity out.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Actions</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getActivity_Actions()
	 * @model
	 * @generated
	 */
	EList<Action> getActions();

} // Activity
