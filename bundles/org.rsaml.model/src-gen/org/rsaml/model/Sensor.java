/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Sensor</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A device that lets the robot perceive its environment.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Sensor#getArchitecture <em>Architecture</em>}</li>
 *   <li>{@link org.rsaml.model.Sensor#getModules <em>Modules</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getSensor()
 * @model
 * @generated
 */
public interface Sensor extends Device {
	/**
	 * Returns the value of the '<em><b>Architecture</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Architecture#getSensors <em>Sensors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The architecture that contains this sensor.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Architecture</em>' container reference.
	 * @see #setArchitecture(Architecture)
	 * @see org.rsaml.model.RsamlPackage#getSensor_Architecture()
	 * @see org.rsaml.model.Architecture#getSensors
	 * @model opposite="sensors"
	 * @generated
	 */
	Architecture getArchitecture();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Sensor#getArchitecture <em>Architecture</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Architecture</em>' container reference.
	 * @see #getArchitecture()
	 * @generated
	 */
	void setArchitecture(Architecture value);

	/**
	 * Returns the value of the '<em><b>Modules</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Module}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Module#getSensors <em>Sensors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The modules that read this sensor.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Modules</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getSensor_Modules()
	 * @see org.rsaml.model.Module#getSensors
	 * @model opposite="sensors" transient="true"
	 * @generated
	 */
	EList<org.rsaml.model.Module> getModules();

} // Sensor
