/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;


/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Device</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A piece of the robot's hardware that modules use.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Device#getKind <em>Kind</em>}</li>
 *   <li>{@link org.rsaml.model.Device#getDataType <em>Data Type</em>}</li>
 *   <li>{@link org.rsaml.model.Device#getPeriod <em>Period</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getDevice()
 * @model abstract="true"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA13_nonNegativeTimes RSA20_representableTimes'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA13_nonNegativeTimes='period &gt;= 0' RSA20_representableTimes='representablePeriod(period)'"
 * @generated
 */
public interface Device extends NamedElement, TimeScaled {
	/**
	 * Returns the value of the '<em><b>Kind</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * What kind of device it is (for example lidar, camera, wheel motor).
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Kind</em>' attribute.
	 * @see #setKind(String)
	 * @see org.rsaml.model.RsamlPackage#getDevice_Kind()
	 * @model
	 * @generated
	 */
	String getKind();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Device#getKind <em>Kind</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Kind</em>' attribute.
	 * @see #getKind()
	 * @generated
	 */
	void setKind(String value);

	/**
	 * Returns the value of the '<em><b>Data Type</b></em>' attribute.
	 * The default value is <code>"numeric"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.DataType}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The type of data the device produces or consumes.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Data Type</em>' attribute.
	 * @see org.rsaml.model.DataType
	 * @see #setDataType(DataType)
	 * @see org.rsaml.model.RsamlPackage#getDevice_DataType()
	 * @model default="numeric"
	 * @generated
	 */
	DataType getDataType();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Device#getDataType <em>Data Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Data Type</em>' attribute.
	 * @see org.rsaml.model.DataType
	 * @see #getDataType()
	 * @generated
	 */
	void setDataType(DataType value);

	/**
	 * Returns the value of the '<em><b>Period</b></em>' attribute.
	 * The default value is <code>"0.0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The sampling or command period of the device, in its time unit; 0 when event-driven.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Period</em>' attribute.
	 * @see #setPeriod(double)
	 * @see org.rsaml.model.RsamlPackage#getDevice_Period()
	 * @model default="0.0"
	 * @generated
	 */
	double getPeriod();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Device#getPeriod <em>Period</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Period</em>' attribute.
	 * @see #getPeriod()
	 * @generated
	 */
	void setPeriod(double value);

} // Device
