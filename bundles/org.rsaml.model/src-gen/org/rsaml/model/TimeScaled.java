/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.ecore.EObject;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Time Scaled</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * An element whose time values are expressed in a time unit. Values of elements with different units are compared exactly, by decimal scaling of the written values (compareTime).
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.TimeScaled#getTimeUnit <em>Time Unit</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getTimeScaled()
 * @model interface="true" abstract="true"
 * @generated
 */
public interface TimeScaled extends EObject {
	/**
	 * Returns the value of the '<em><b>Time Unit</b></em>' attribute.
	 * The default value is <code>"ms"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.TimeUnit}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The unit of this element's time values (timeUnit); milliseconds when not set.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Time Unit</em>' attribute.
	 * @see org.rsaml.model.TimeUnit
	 * @see #setTimeUnit(TimeUnit)
	 * @see org.rsaml.model.RsamlPackage#getTimeScaled_TimeUnit()
	 * @model default="ms"
	 * @generated
	 */
	TimeUnit getTimeUnit();

	/**
	 * Sets the value of the '{@link org.rsaml.model.TimeScaled#getTimeUnit <em>Time Unit</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Time Unit</em>' attribute.
	 * @see org.rsaml.model.TimeUnit
	 * @see #getTimeUnit()
	 * @generated
	 */
	void setTimeUnit(TimeUnit value);

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Converts a time value expressed in this element's time unit to milliseconds, so that values of different units can be compared.
	 * <!-- end-model-doc -->
	 * @model
	 * @generated
	 */
	double toMilliseconds(double value);

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Compares a time value in this element's unit with one in another element's unit, exactly (decimal scaling of the written values): negative, zero or positive as this one is shorter, equal or longer.
	 * <!-- end-model-doc -->
	 * @model
	 * @generated
	 */
	int compareTime(double value, TimeScaled other, double otherValue);

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Whether a time value in this element's unit fits the generated code's clock: finite and at most 2^60 nanoseconds (about 36.5 years).
	 * <!-- end-model-doc -->
	 * @model
	 * @generated
	 */
	boolean representable(double value);

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Whether a period in this element's unit fits the generated code's timers: representable, and 0 (no period) or at least 1 nanosecond.
	 * <!-- end-model-doc -->
	 * @model
	 * @generated
	 */
	boolean representablePeriod(double value);

} // TimeScaled
