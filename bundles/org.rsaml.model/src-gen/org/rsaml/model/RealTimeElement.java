/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;


/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Real Time Element</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * An element that executes and can carry real-time properties: an activity, a module, a function or an action.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.RealTimeElement#getType <em>Type</em>}</li>
 *   <li>{@link org.rsaml.model.RealTimeElement#getPeriod <em>Period</em>}</li>
 *   <li>{@link org.rsaml.model.RealTimeElement#getDelay <em>Delay</em>}</li>
 *   <li>{@link org.rsaml.model.RealTimeElement#getExecDuration <em>Exec Duration</em>}</li>
 *   <li>{@link org.rsaml.model.RealTimeElement#getExecType <em>Exec Type</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getRealTimeElement()
 * @model abstract="true"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA10_executionWithinPeriod RSA11_deadlineWithinPeriod RSA12_periodicHasPeriod RSA13_nonNegativeTimes RSA17_executionWithinDeadline RSA20_representableTimes'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA10_executionWithinPeriod='(execType = ExecutionType::periodic and period &gt; 0) implies execDuration &lt;= period' RSA11_deadlineWithinPeriod='(execType = ExecutionType::periodic and period &gt; 0 and delay &gt; 0) implies delay &lt;= period' RSA12_periodicHasPeriod='execType = ExecutionType::periodic implies period &gt; 0' RSA13_nonNegativeTimes='period &gt;= 0 and delay &gt;= 0 and execDuration &gt;= 0' RSA17_executionWithinDeadline='(type = ElementType::realTime and delay &gt; 0) implies execDuration &lt;= delay' RSA20_representableTimes='representablePeriod(period) and representable(delay) and representable(execDuration)'"
 * @generated
 */
public interface RealTimeElement extends NamedElement, TimeScaled {
	/**
	 * Returns the value of the '<em><b>Type</b></em>' attribute.
	 * The default value is <code>"simple"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.ElementType}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Whether the element is simple or real-time (type). A real-time element must meet its timing properties.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Type</em>' attribute.
	 * @see org.rsaml.model.ElementType
	 * @see #setType(ElementType)
	 * @see org.rsaml.model.RsamlPackage#getRealTimeElement_Type()
	 * @model default="simple"
	 * @generated
	 */
	ElementType getType();

	/**
	 * Sets the value of the '{@link org.rsaml.model.RealTimeElement#getType <em>Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Type</em>' attribute.
	 * @see org.rsaml.model.ElementType
	 * @see #getType()
	 * @generated
	 */
	void setType(ElementType value);

	/**
	 * Returns the value of the '<em><b>Period</b></em>' attribute.
	 * The default value is <code>"0.0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Period of execution, in the element's time unit. For a sporadic element it is the minimum time between two activations; 0 means none.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Period</em>' attribute.
	 * @see #setPeriod(double)
	 * @see org.rsaml.model.RsamlPackage#getRealTimeElement_Period()
	 * @model default="0.0"
	 * @generated
	 */
	double getPeriod();

	/**
	 * Sets the value of the '{@link org.rsaml.model.RealTimeElement#getPeriod <em>Period</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Period</em>' attribute.
	 * @see #getPeriod()
	 * @generated
	 */
	void setPeriod(double value);

	/**
	 * Returns the value of the '<em><b>Delay</b></em>' attribute.
	 * The default value is <code>"0.0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Response time (delay): the deadline by which an activation must complete, relative to its release, in the element's time unit.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Delay</em>' attribute.
	 * @see #setDelay(double)
	 * @see org.rsaml.model.RsamlPackage#getRealTimeElement_Delay()
	 * @model default="0.0"
	 * @generated
	 */
	double getDelay();

	/**
	 * Sets the value of the '{@link org.rsaml.model.RealTimeElement#getDelay <em>Delay</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Delay</em>' attribute.
	 * @see #getDelay()
	 * @generated
	 */
	void setDelay(double value);

	/**
	 * Returns the value of the '<em><b>Exec Duration</b></em>' attribute.
	 * The default value is <code>"0.0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Execution duration: the worst-case time one activation takes, in the element's time unit.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Exec Duration</em>' attribute.
	 * @see #setExecDuration(double)
	 * @see org.rsaml.model.RsamlPackage#getRealTimeElement_ExecDuration()
	 * @model default="0.0"
	 * @generated
	 */
	double getExecDuration();

	/**
	 * Sets the value of the '{@link org.rsaml.model.RealTimeElement#getExecDuration <em>Exec Duration</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Exec Duration</em>' attribute.
	 * @see #getExecDuration()
	 * @generated
	 */
	void setExecDuration(double value);

	/**
	 * Returns the value of the '<em><b>Exec Type</b></em>' attribute.
	 * The default value is <code>"aperiodic"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.ExecutionType}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * How the element is activated (execType): periodically, sporadically or aperiodically.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Exec Type</em>' attribute.
	 * @see org.rsaml.model.ExecutionType
	 * @see #setExecType(ExecutionType)
	 * @see org.rsaml.model.RsamlPackage#getRealTimeElement_ExecType()
	 * @model default="aperiodic"
	 * @generated
	 */
	ExecutionType getExecType();

	/**
	 * Sets the value of the '{@link org.rsaml.model.RealTimeElement#getExecType <em>Exec Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Exec Type</em>' attribute.
	 * @see org.rsaml.model.ExecutionType
	 * @see #getExecType()
	 * @generated
	 */
	void setExecType(ExecutionType value);

} // RealTimeElement
