/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;


/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Action</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A basic task of the robot, performed by a function.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Action#getFunction <em>Function</em>}</li>
 *   <li>{@link org.rsaml.model.Action#getStartDate <em>Start Date</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getAction()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA27_actionWithinBudget'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA27_actionWithinBudget='(function &lt;&gt; null and function.execDuration &gt; 0 implies compareTime(execDuration, function, function.execDuration) &lt;= 0) and ((function &lt;&gt; null and function.module &lt;&gt; null and function.module.execDuration &gt; 0) implies compareTime(execDuration, function.module, function.module.execDuration) &lt;= 0) and ((function &lt;&gt; null and function.module &lt;&gt; null and function.module.layer &lt;&gt; null and function.module.layer.maxExecTime &gt; 0) implies compareTime(execDuration, function.module.layer, function.module.layer.maxExecTime) &lt;= 0)'"
 * @generated
 */
public interface Action extends RealTimeElement {
	/**
	 * Returns the value of the '<em><b>Function</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Function#getActions <em>Actions</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The function that performs this action.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Function</em>' container reference.
	 * @see #setFunction(Function)
	 * @see org.rsaml.model.RsamlPackage#getAction_Function()
	 * @see org.rsaml.model.Function#getActions
	 * @model opposite="actions"
	 * @generated
	 */
	Function getFunction();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Action#getFunction <em>Function</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Function</em>' container reference.
	 * @see #getFunction()
	 * @generated
	 */
	void setFunction(Function value);

	/**
	 * Returns the value of the '<em><b>Start Date</b></em>' attribute.
	 * The default value is <code>"0.0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Start time (startDate) of the action's first release, relative to the start of the system, in the action's time unit.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Start Date</em>' attribute.
	 * @see #setStartDate(double)
	 * @see org.rsaml.model.RsamlPackage#getAction_StartDate()
	 * @model default="0.0"
	 * @generated
	 */
	double getStartDate();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Action#getStartDate <em>Start Date</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Start Date</em>' attribute.
	 * @see #getStartDate()
	 * @generated
	 */
	void setStartDate(double value);

} // Action
