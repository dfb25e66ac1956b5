/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Function</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A service a module offers, implemented by a sequence of actions, with its synchronisation type and scheduling policy.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Function#getModule <em>Module</em>}</li>
 *   <li>{@link org.rsaml.model.Function#getActions <em>Actions</em>}</li>
 *   <li>{@link org.rsaml.model.Function#getSynchroType <em>Synchro Type</em>}</li>
 *   <li>{@link org.rsaml.model.Function#getSchedPolicy <em>Sched Policy</em>}</li>
 *   <li>{@link org.rsaml.model.Function#getOtherPolicy <em>Other Policy</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getFunction()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA07_realTimeFunctionActions RSA09_uniqueNames RSA27_functionWithinBudget'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA07_realTimeFunctionActions='type = ElementType::realTime implies actions-&gt;forAll(a | a.type = ElementType::realTime)' RSA09_uniqueNames='actions-&gt;isUnique(normalizedName())' RSA27_functionWithinBudget='(module &lt;&gt; null and module.execDuration &gt; 0 implies compareTime(execDuration, module, module.execDuration) &lt;= 0) and ((module &lt;&gt; null and module.layer &lt;&gt; null and module.layer.maxExecTime &gt; 0) implies compareTime(execDuration, module.layer, module.layer.maxExecTime) &lt;= 0)'"
 * @generated
 */
public interface Function extends RealTimeElement {
	/**
	 * Returns the value of the '<em><b>Module</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Module#getFunctions <em>Functions</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The module that offers this function.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Module</em>' container reference.
	 * @see #setModule(org.rsaml.model.Module)
	 * @see org.rsaml.model.RsamlPackage#getFunction_Module()
	 * @see org.rsaml.model.Module#getFunctions
	 * @model opposite="functions"
	 * @generated
	 */
	org.rsaml.model.Module getModule();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Function#getModule <em>Module</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Module</em>' container reference.
	 * @see #getModule()
	 * @generated
	 */
	void setModule(org.rsaml.model.Module value);

	/**
	 * Returns the value of the '<em><b>Actions</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Action}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Action#getFunction <em>Function</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The actions the function performs, in order.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Actions</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getFunction_Actions()
	 * @see org.rsaml.model.Action#getFunction
	 * @model opposite="function" containment="true" keys="name"
	 * @generated
	 */
	EList<Action> getActions();

	/**
	 * Returns the value of the '<em><b>Synchro Type</b></em>' attribute.
	 * The default value is <code>"synchronous"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.SynchronisationType}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Whether a caller waits for the function to complete (synchronous) or not (asynchronous).
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Synchro Type</em>' attribute.
	 * @see org.rsaml.model.SynchronisationType
	 * @see #setSynchroType(SynchronisationType)
	 * @see org.rsaml.model.RsamlPackage#getFunction_SynchroType()
	 * @model default="synchronous"
	 * @generated
	 */
	SynchronisationType getSynchroType();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Function#getSynchroType <em>Synchro Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Synchro Type</em>' attribute.
	 * @see org.rsaml.model.SynchronisationType
	 * @see #getSynchroType()
	 * @generated
	 */
	void setSynchroType(SynchronisationType value);

	/**
	 * Returns the value of the '<em><b>Sched Policy</b></em>' attribute.
	 * The default value is <code>"FIFO"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.SchedulingPolicy}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The scheduling policy of the function's actions (schedPolicy): FIFO, SJF, RR, RM, DM, EDF, LLF, or another policy named in otherPolicy.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Sched Policy</em>' attribute.
	 * @see org.rsaml.model.SchedulingPolicy
	 * @see #setSchedPolicy(SchedulingPolicy)
	 * @see org.rsaml.model.RsamlPackage#getFunction_SchedPolicy()
	 * @model default="FIFO"
	 * @generated
	 */
	SchedulingPolicy getSchedPolicy();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Function#getSchedPolicy <em>Sched Policy</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Sched Policy</em>' attribute.
	 * @see org.rsaml.model.SchedulingPolicy
	 * @see #getSchedPolicy()
	 * @generated
	 */
	void setSchedPolicy(SchedulingPolicy value);

	/**
	 * Returns the value of the '<em><b>Other Policy</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The name of the scheduling policy when schedPolicy is OTHER.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Other Policy</em>' attribute.
	 * @see #setOtherPolicy(String)
	 * @see org.rsaml.model.RsamlPackage#getFunction_OtherPolicy()
	 * @model
	 * @generated
	 */
	String getOtherPolicy();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Function#getOtherPolicy <em>Other Policy</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Other Policy</em>' attribute.
	 * @see #getOtherPolicy()
	 * @generated
	 */
	void setOtherPolicy(String value);

} // Function
