/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;


/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Subsumption Link</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A subsumption link of a behavioral architecture: while the owning module emits on the trigger port, the link takes control of a port of another module for the given duration.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.SubsumptionLink#getTrigger <em>Trigger</em>}</li>
 *   <li>{@link org.rsaml.model.SubsumptionLink#getDuration <em>Duration</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getSubsumptionLink()
 * @model abstract="true"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA13_nonNegativeTimes RSA20_representableTimes RSA26_durationBelowTriggerPeriod'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA13_nonNegativeTimes='duration &gt;= 0' RSA20_representableTimes='representable(duration)' RSA26_durationBelowTriggerPeriod='(trigger &lt;&gt; null and trigger.module &lt;&gt; null and duration &gt; 0) implies (((trigger.module.execType = ExecutionType::periodic and trigger.module.period &gt; 0) and (trigger.module.functions-&gt;exists(f | not (f.execType = ExecutionType::periodic and f.period &gt; 0)) or not trigger.module.functions-&gt;exists(f | (f.execType = ExecutionType::periodic and f.period &gt; 0) or f.actions-&gt;exists(a | (a.execType = ExecutionType::periodic and a.period &gt; 0)))) implies trigger.module.compareTime(trigger.module.period, self, duration) &gt; 0) and trigger.module.functions-&gt;forAll(f | (f.execType = ExecutionType::periodic and f.period &gt; 0) implies f.compareTime(f.period, self, duration) &gt; 0) and trigger.module.functions-&gt;forAll(f | f.actions-&gt;forAll(a | (a.execType = ExecutionType::periodic and a.period &gt; 0) implies a.compareTime(a.period, self, duration) &gt; 0)))'"
 * @generated
 */
public interface SubsumptionLink extends NamedElement, TimeScaled {
	/**
	 * Returns the value of the '<em><b>Trigger</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The output port of the owning module whose messages activate the link; for a suppressor, these messages also replace the suppressed input.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Trigger</em>' reference.
	 * @see #setTrigger(OutputPort)
	 * @see org.rsaml.model.RsamlPackage#getSubsumptionLink_Trigger()
	 * @model
	 * @generated
	 */
	OutputPort getTrigger();

	/**
	 * Sets the value of the '{@link org.rsaml.model.SubsumptionLink#getTrigger <em>Trigger</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Trigger</em>' reference.
	 * @see #getTrigger()
	 * @generated
	 */
	void setTrigger(OutputPort value);

	/**
	 * Returns the value of the '<em><b>Duration</b></em>' attribute.
	 * The default value is <code>"0.0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * How long the link stays active after each trigger message, in the link's time unit.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Duration</em>' attribute.
	 * @see #setDuration(double)
	 * @see org.rsaml.model.RsamlPackage#getSubsumptionLink_Duration()
	 * @model default="0.0"
	 * @generated
	 */
	double getDuration();

	/**
	 * Sets the value of the '{@link org.rsaml.model.SubsumptionLink#getDuration <em>Duration</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Duration</em>' attribute.
	 * @see #getDuration()
	 * @generated
	 */
	void setDuration(double value);

} // SubsumptionLink
