/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EOperation;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EReference;

/**
 * <!-- begin-user-doc -->
 * The <b>Package</b> for the model.
 * It contains accessors for the meta objects to represent
 * <ul>
 *   <li>each class,</li>
 *   <li>each feature of each class,</li>
 *   <li>each operation of each class,</li>
 *   <li>each enum,</li>
 *   <li>and each data type</li>
 * </ul>
 * <!-- end-user-doc -->
 * <!-- begin-model-doc -->
 * RsaML, the Robotic Software Architecture Modeling Language: layers, modules, functions, actions, ports, sensors, actuators, inhibitors and suppressors, missions, goals, plans and supervisors of a robot's software architecture, with their real-time properties.
 * <!-- end-model-doc -->
 * @see org.rsaml.model.RsamlFactory
 * @model kind="package"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore invocationDelegates='http://www.eclipse.org/emf/2002/Ecore/OCL' settingDelegates='http://www.eclipse.org/emf/2002/Ecore/OCL'"
 * @generated
 */
public interface RsamlPackage extends EPackage {
	/**
	 * The package name.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	String eNAME = "model";

	/**
	 * The package namespace URI.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	String eNS_URI = "http://www.rsaml.org/rsaml/1.0";

	/**
	 * The package namespace name.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	String eNS_PREFIX = "rsaml";

	/**
	 * The package content type ID.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	String eCONTENT_TYPE = "org.rsaml.model.rsaml";

	/**
	 * The singleton instance of the package.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	RsamlPackage eINSTANCE = org.rsaml.model.impl.RsamlPackageImpl.init();

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.NamedElementImpl <em>Named Element</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.NamedElementImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getNamedElement()
	 * @generated
	 */
	int NAMED_ELEMENT = 0;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int NAMED_ELEMENT__NAME = 0;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int NAMED_ELEMENT__DESCRIPTION = 1;

	/**
	 * The number of structural features of the '<em>Named Element</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int NAMED_ELEMENT_FEATURE_COUNT = 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int NAMED_ELEMENT___NORMALIZED_NAME = 0;

	/**
	 * The number of operations of the '<em>Named Element</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int NAMED_ELEMENT_OPERATION_COUNT = 1;

	/**
	 * The meta object id for the '{@link org.rsaml.model.TimeScaled <em>Time Scaled</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.TimeScaled
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getTimeScaled()
	 * @generated
	 */
	int TIME_SCALED = 1;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int TIME_SCALED__TIME_UNIT = 0;

	/**
	 * The number of structural features of the '<em>Time Scaled</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int TIME_SCALED_FEATURE_COUNT = 1;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int TIME_SCALED___TO_MILLISECONDS__DOUBLE = 0;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int TIME_SCALED___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = 1;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int TIME_SCALED___REPRESENTABLE__DOUBLE = 2;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int TIME_SCALED___REPRESENTABLE_PERIOD__DOUBLE = 3;

	/**
	 * The number of operations of the '<em>Time Scaled</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int TIME_SCALED_OPERATION_COUNT = 4;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.RealTimeElementImpl <em>Real Time Element</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.RealTimeElementImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getRealTimeElement()
	 * @generated
	 */
	int REAL_TIME_ELEMENT = 2;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT__TIME_UNIT = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT__TYPE = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Period</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT__PERIOD = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Delay</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT__DELAY = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The feature id for the '<em><b>Exec Duration</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT__EXEC_DURATION = NAMED_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The feature id for the '<em><b>Exec Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT__EXEC_TYPE = NAMED_ELEMENT_FEATURE_COUNT + 5;

	/**
	 * The number of structural features of the '<em>Real Time Element</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 6;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT___TO_MILLISECONDS__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 1;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT___REPRESENTABLE__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 2;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT___REPRESENTABLE_PERIOD__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 3;

	/**
	 * The number of operations of the '<em>Real Time Element</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int REAL_TIME_ELEMENT_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 4;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.ArchitectureImpl <em>Architecture</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.ArchitectureImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getArchitecture()
	 * @generated
	 */
	int ARCHITECTURE = 3;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Category</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__CATEGORY = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Declared Layers</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__DECLARED_LAYERS = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Lifecycle</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__LIFECYCLE = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Packages</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__PACKAGES = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The feature id for the '<em><b>Layers</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__LAYERS = NAMED_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The feature id for the '<em><b>Connections</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__CONNECTIONS = NAMED_ELEMENT_FEATURE_COUNT + 5;

	/**
	 * The feature id for the '<em><b>Sensors</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__SENSORS = NAMED_ELEMENT_FEATURE_COUNT + 6;

	/**
	 * The feature id for the '<em><b>Actuators</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__ACTUATORS = NAMED_ELEMENT_FEATURE_COUNT + 7;

	/**
	 * The feature id for the '<em><b>Missions</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__MISSIONS = NAMED_ELEMENT_FEATURE_COUNT + 8;

	/**
	 * The feature id for the '<em><b>Supervisors</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__SUPERVISORS = NAMED_ELEMENT_FEATURE_COUNT + 9;

	/**
	 * The feature id for the '<em><b>Orders</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__ORDERS = NAMED_ELEMENT_FEATURE_COUNT + 10;

	/**
	 * The feature id for the '<em><b>Databases</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__DATABASES = NAMED_ELEMENT_FEATURE_COUNT + 11;

	/**
	 * The feature id for the '<em><b>Processors</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__PROCESSORS = NAMED_ELEMENT_FEATURE_COUNT + 12;

	/**
	 * The feature id for the '<em><b>Latency Requirements</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE__LATENCY_REQUIREMENTS = NAMED_ELEMENT_FEATURE_COUNT + 13;

	/**
	 * The number of structural features of the '<em>Architecture</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 14;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The number of operations of the '<em>Architecture</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ARCHITECTURE_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.LayerImpl <em>Layer</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.LayerImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getLayer()
	 * @generated
	 */
	int LAYER = 4;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER__TIME_UNIT = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Architecture</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER__ARCHITECTURE = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Level</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER__LEVEL = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Max Exec Time</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER__MAX_EXEC_TIME = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The feature id for the '<em><b>Modules</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER__MODULES = NAMED_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The number of structural features of the '<em>Layer</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 5;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER___TO_MILLISECONDS__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 1;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER___REPRESENTABLE__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 2;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER___REPRESENTABLE_PERIOD__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 3;

	/**
	 * The operation id for the '<em>Package Problem</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER___PACKAGE_PROBLEM = NAMED_ELEMENT_OPERATION_COUNT + 4;

	/**
	 * The number of operations of the '<em>Layer</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LAYER_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 5;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.ModuleImpl <em>Module</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.ModuleImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getModule()
	 * @generated
	 */
	int MODULE = 5;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__NAME = REAL_TIME_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__DESCRIPTION = REAL_TIME_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__TIME_UNIT = REAL_TIME_ELEMENT__TIME_UNIT;

	/**
	 * The feature id for the '<em><b>Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__TYPE = REAL_TIME_ELEMENT__TYPE;

	/**
	 * The feature id for the '<em><b>Period</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__PERIOD = REAL_TIME_ELEMENT__PERIOD;

	/**
	 * The feature id for the '<em><b>Delay</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__DELAY = REAL_TIME_ELEMENT__DELAY;

	/**
	 * The feature id for the '<em><b>Exec Duration</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__EXEC_DURATION = REAL_TIME_ELEMENT__EXEC_DURATION;

	/**
	 * The feature id for the '<em><b>Exec Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__EXEC_TYPE = REAL_TIME_ELEMENT__EXEC_TYPE;

	/**
	 * The feature id for the '<em><b>Layer</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__LAYER = REAL_TIME_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Functions</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__FUNCTIONS = REAL_TIME_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Ports</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__PORTS = REAL_TIME_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Inhibitors</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__INHIBITORS = REAL_TIME_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The feature id for the '<em><b>Suppressors</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__SUPPRESSORS = REAL_TIME_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The feature id for the '<em><b>Sensors</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__SENSORS = REAL_TIME_ELEMENT_FEATURE_COUNT + 5;

	/**
	 * The feature id for the '<em><b>Actuators</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__ACTUATORS = REAL_TIME_ELEMENT_FEATURE_COUNT + 6;

	/**
	 * The feature id for the '<em><b>Lifecycle</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE__LIFECYCLE = REAL_TIME_ELEMENT_FEATURE_COUNT + 7;

	/**
	 * The number of structural features of the '<em>Module</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE_FEATURE_COUNT = REAL_TIME_ELEMENT_FEATURE_COUNT + 8;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE___NORMALIZED_NAME = REAL_TIME_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE___TO_MILLISECONDS__DOUBLE = REAL_TIME_ELEMENT___TO_MILLISECONDS__DOUBLE;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = REAL_TIME_ELEMENT___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE___REPRESENTABLE__DOUBLE = REAL_TIME_ELEMENT___REPRESENTABLE__DOUBLE;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE___REPRESENTABLE_PERIOD__DOUBLE = REAL_TIME_ELEMENT___REPRESENTABLE_PERIOD__DOUBLE;

	/**
	 * The operation id for the '<em>Effective Lifecycle</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE___EFFECTIVE_LIFECYCLE = REAL_TIME_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The number of operations of the '<em>Module</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MODULE_OPERATION_COUNT = REAL_TIME_ELEMENT_OPERATION_COUNT + 1;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.FunctionImpl <em>Function</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.FunctionImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getFunction()
	 * @generated
	 */
	int FUNCTION = 6;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__NAME = REAL_TIME_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__DESCRIPTION = REAL_TIME_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__TIME_UNIT = REAL_TIME_ELEMENT__TIME_UNIT;

	/**
	 * The feature id for the '<em><b>Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__TYPE = REAL_TIME_ELEMENT__TYPE;

	/**
	 * The feature id for the '<em><b>Period</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__PERIOD = REAL_TIME_ELEMENT__PERIOD;

	/**
	 * The feature id for the '<em><b>Delay</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__DELAY = REAL_TIME_ELEMENT__DELAY;

	/**
	 * The feature id for the '<em><b>Exec Duration</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__EXEC_DURATION = REAL_TIME_ELEMENT__EXEC_DURATION;

	/**
	 * The feature id for the '<em><b>Exec Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__EXEC_TYPE = REAL_TIME_ELEMENT__EXEC_TYPE;

	/**
	 * The feature id for the '<em><b>Module</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__MODULE = REAL_TIME_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Actions</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__ACTIONS = REAL_TIME_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Synchro Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__SYNCHRO_TYPE = REAL_TIME_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Sched Policy</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__SCHED_POLICY = REAL_TIME_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The feature id for the '<em><b>Other Policy</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION__OTHER_POLICY = REAL_TIME_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The number of structural features of the '<em>Function</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION_FEATURE_COUNT = REAL_TIME_ELEMENT_FEATURE_COUNT + 5;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION___NORMALIZED_NAME = REAL_TIME_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION___TO_MILLISECONDS__DOUBLE = REAL_TIME_ELEMENT___TO_MILLISECONDS__DOUBLE;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = REAL_TIME_ELEMENT___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION___REPRESENTABLE__DOUBLE = REAL_TIME_ELEMENT___REPRESENTABLE__DOUBLE;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION___REPRESENTABLE_PERIOD__DOUBLE = REAL_TIME_ELEMENT___REPRESENTABLE_PERIOD__DOUBLE;

	/**
	 * The number of operations of the '<em>Function</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int FUNCTION_OPERATION_COUNT = REAL_TIME_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.ActionImpl <em>Action</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.ActionImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getAction()
	 * @generated
	 */
	int ACTION = 7;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__NAME = REAL_TIME_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__DESCRIPTION = REAL_TIME_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__TIME_UNIT = REAL_TIME_ELEMENT__TIME_UNIT;

	/**
	 * The feature id for the '<em><b>Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__TYPE = REAL_TIME_ELEMENT__TYPE;

	/**
	 * The feature id for the '<em><b>Period</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__PERIOD = REAL_TIME_ELEMENT__PERIOD;

	/**
	 * The feature id for the '<em><b>Delay</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__DELAY = REAL_TIME_ELEMENT__DELAY;

	/**
	 * The feature id for the '<em><b>Exec Duration</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__EXEC_DURATION = REAL_TIME_ELEMENT__EXEC_DURATION;

	/**
	 * The feature id for the '<em><b>Exec Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__EXEC_TYPE = REAL_TIME_ELEMENT__EXEC_TYPE;

	/**
	 * The feature id for the '<em><b>Function</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__FUNCTION = REAL_TIME_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Start Date</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION__START_DATE = REAL_TIME_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The number of structural features of the '<em>Action</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION_FEATURE_COUNT = REAL_TIME_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION___NORMALIZED_NAME = REAL_TIME_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION___TO_MILLISECONDS__DOUBLE = REAL_TIME_ELEMENT___TO_MILLISECONDS__DOUBLE;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = REAL_TIME_ELEMENT___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION___REPRESENTABLE__DOUBLE = REAL_TIME_ELEMENT___REPRESENTABLE__DOUBLE;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION___REPRESENTABLE_PERIOD__DOUBLE = REAL_TIME_ELEMENT___REPRESENTABLE_PERIOD__DOUBLE;

	/**
	 * The number of operations of the '<em>Action</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTION_OPERATION_COUNT = REAL_TIME_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.RTActionImpl <em>RT Action</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.RTActionImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getRTAction()
	 * @generated
	 */
	int RT_ACTION = 8;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__NAME = ACTION__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__DESCRIPTION = ACTION__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__TIME_UNIT = ACTION__TIME_UNIT;

	/**
	 * The feature id for the '<em><b>Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__TYPE = ACTION__TYPE;

	/**
	 * The feature id for the '<em><b>Period</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__PERIOD = ACTION__PERIOD;

	/**
	 * The feature id for the '<em><b>Delay</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__DELAY = ACTION__DELAY;

	/**
	 * The feature id for the '<em><b>Exec Duration</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__EXEC_DURATION = ACTION__EXEC_DURATION;

	/**
	 * The feature id for the '<em><b>Exec Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__EXEC_TYPE = ACTION__EXEC_TYPE;

	/**
	 * The feature id for the '<em><b>Function</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__FUNCTION = ACTION__FUNCTION;

	/**
	 * The feature id for the '<em><b>Start Date</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION__START_DATE = ACTION__START_DATE;

	/**
	 * The number of structural features of the '<em>RT Action</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION_FEATURE_COUNT = ACTION_FEATURE_COUNT + 0;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION___NORMALIZED_NAME = ACTION___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION___TO_MILLISECONDS__DOUBLE = ACTION___TO_MILLISECONDS__DOUBLE;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = ACTION___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION___REPRESENTABLE__DOUBLE = ACTION___REPRESENTABLE__DOUBLE;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION___REPRESENTABLE_PERIOD__DOUBLE = ACTION___REPRESENTABLE_PERIOD__DOUBLE;

	/**
	 * The number of operations of the '<em>RT Action</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int RT_ACTION_OPERATION_COUNT = ACTION_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.PortImpl <em>Port</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.PortImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getPort()
	 * @generated
	 */
	int PORT = 9;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Module</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT__MODULE = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Data Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT__DATA_TYPE = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Message Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT__MESSAGE_TYPE = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Topic</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT__TOPIC = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The number of structural features of the '<em>Port</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>Normalized Message Type</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT___NORMALIZED_MESSAGE_TYPE = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The operation id for the '<em>Topic Problem</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT___TOPIC_PROBLEM = NAMED_ELEMENT_OPERATION_COUNT + 1;

	/**
	 * The number of operations of the '<em>Port</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PORT_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 2;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.EntryPortImpl <em>Entry Port</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.EntryPortImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getEntryPort()
	 * @generated
	 */
	int ENTRY_PORT = 10;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT__NAME = PORT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT__DESCRIPTION = PORT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Module</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT__MODULE = PORT__MODULE;

	/**
	 * The feature id for the '<em><b>Data Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT__DATA_TYPE = PORT__DATA_TYPE;

	/**
	 * The feature id for the '<em><b>Message Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT__MESSAGE_TYPE = PORT__MESSAGE_TYPE;

	/**
	 * The feature id for the '<em><b>Topic</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT__TOPIC = PORT__TOPIC;

	/**
	 * The feature id for the '<em><b>Incoming</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT__INCOMING = PORT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Suppressed By</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT__SUPPRESSED_BY = PORT_FEATURE_COUNT + 1;

	/**
	 * The number of structural features of the '<em>Entry Port</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT_FEATURE_COUNT = PORT_FEATURE_COUNT + 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT___NORMALIZED_NAME = PORT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>Normalized Message Type</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT___NORMALIZED_MESSAGE_TYPE = PORT___NORMALIZED_MESSAGE_TYPE;

	/**
	 * The operation id for the '<em>Topic Problem</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT___TOPIC_PROBLEM = PORT___TOPIC_PROBLEM;

	/**
	 * The number of operations of the '<em>Entry Port</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ENTRY_PORT_OPERATION_COUNT = PORT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.OutputPortImpl <em>Output Port</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.OutputPortImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getOutputPort()
	 * @generated
	 */
	int OUTPUT_PORT = 11;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT__NAME = PORT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT__DESCRIPTION = PORT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Module</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT__MODULE = PORT__MODULE;

	/**
	 * The feature id for the '<em><b>Data Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT__DATA_TYPE = PORT__DATA_TYPE;

	/**
	 * The feature id for the '<em><b>Message Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT__MESSAGE_TYPE = PORT__MESSAGE_TYPE;

	/**
	 * The feature id for the '<em><b>Topic</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT__TOPIC = PORT__TOPIC;

	/**
	 * The feature id for the '<em><b>Outgoing</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT__OUTGOING = PORT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Inhibited By</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT__INHIBITED_BY = PORT_FEATURE_COUNT + 1;

	/**
	 * The number of structural features of the '<em>Output Port</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT_FEATURE_COUNT = PORT_FEATURE_COUNT + 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT___NORMALIZED_NAME = PORT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>Normalized Message Type</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT___NORMALIZED_MESSAGE_TYPE = PORT___NORMALIZED_MESSAGE_TYPE;

	/**
	 * The operation id for the '<em>Topic Problem</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT___TOPIC_PROBLEM = PORT___TOPIC_PROBLEM;

	/**
	 * The number of operations of the '<em>Output Port</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int OUTPUT_PORT_OPERATION_COUNT = PORT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.ConnectionImpl <em>Connection</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.ConnectionImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getConnection()
	 * @generated
	 */
	int CONNECTION = 12;

	/**
	 * The feature id for the '<em><b>Architecture</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int CONNECTION__ARCHITECTURE = 0;

	/**
	 * The feature id for the '<em><b>Source</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int CONNECTION__SOURCE = 1;

	/**
	 * The feature id for the '<em><b>Target</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int CONNECTION__TARGET = 2;

	/**
	 * The number of structural features of the '<em>Connection</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int CONNECTION_FEATURE_COUNT = 3;

	/**
	 * The number of operations of the '<em>Connection</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int CONNECTION_OPERATION_COUNT = 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.SubsumptionLinkImpl <em>Subsumption Link</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.SubsumptionLinkImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getSubsumptionLink()
	 * @generated
	 */
	int SUBSUMPTION_LINK = 13;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK__TIME_UNIT = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Trigger</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK__TRIGGER = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Duration</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK__DURATION = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The number of structural features of the '<em>Subsumption Link</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK___TO_MILLISECONDS__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 1;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK___REPRESENTABLE__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 2;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK___REPRESENTABLE_PERIOD__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 3;

	/**
	 * The number of operations of the '<em>Subsumption Link</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUBSUMPTION_LINK_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 4;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.InhibitorImpl <em>Inhibitor</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.InhibitorImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getInhibitor()
	 * @generated
	 */
	int INHIBITOR = 14;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR__NAME = SUBSUMPTION_LINK__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR__DESCRIPTION = SUBSUMPTION_LINK__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR__TIME_UNIT = SUBSUMPTION_LINK__TIME_UNIT;

	/**
	 * The feature id for the '<em><b>Trigger</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR__TRIGGER = SUBSUMPTION_LINK__TRIGGER;

	/**
	 * The feature id for the '<em><b>Duration</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR__DURATION = SUBSUMPTION_LINK__DURATION;

	/**
	 * The feature id for the '<em><b>Module</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR__MODULE = SUBSUMPTION_LINK_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Target</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR__TARGET = SUBSUMPTION_LINK_FEATURE_COUNT + 1;

	/**
	 * The number of structural features of the '<em>Inhibitor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR_FEATURE_COUNT = SUBSUMPTION_LINK_FEATURE_COUNT + 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR___NORMALIZED_NAME = SUBSUMPTION_LINK___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR___TO_MILLISECONDS__DOUBLE = SUBSUMPTION_LINK___TO_MILLISECONDS__DOUBLE;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = SUBSUMPTION_LINK___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR___REPRESENTABLE__DOUBLE = SUBSUMPTION_LINK___REPRESENTABLE__DOUBLE;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR___REPRESENTABLE_PERIOD__DOUBLE = SUBSUMPTION_LINK___REPRESENTABLE_PERIOD__DOUBLE;

	/**
	 * The number of operations of the '<em>Inhibitor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int INHIBITOR_OPERATION_COUNT = SUBSUMPTION_LINK_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.SuppressorImpl <em>Suppressor</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.SuppressorImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getSuppressor()
	 * @generated
	 */
	int SUPPRESSOR = 15;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR__NAME = SUBSUMPTION_LINK__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR__DESCRIPTION = SUBSUMPTION_LINK__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR__TIME_UNIT = SUBSUMPTION_LINK__TIME_UNIT;

	/**
	 * The feature id for the '<em><b>Trigger</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR__TRIGGER = SUBSUMPTION_LINK__TRIGGER;

	/**
	 * The feature id for the '<em><b>Duration</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR__DURATION = SUBSUMPTION_LINK__DURATION;

	/**
	 * The feature id for the '<em><b>Module</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR__MODULE = SUBSUMPTION_LINK_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Target</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR__TARGET = SUBSUMPTION_LINK_FEATURE_COUNT + 1;

	/**
	 * The number of structural features of the '<em>Suppressor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR_FEATURE_COUNT = SUBSUMPTION_LINK_FEATURE_COUNT + 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR___NORMALIZED_NAME = SUBSUMPTION_LINK___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR___TO_MILLISECONDS__DOUBLE = SUBSUMPTION_LINK___TO_MILLISECONDS__DOUBLE;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = SUBSUMPTION_LINK___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR___REPRESENTABLE__DOUBLE = SUBSUMPTION_LINK___REPRESENTABLE__DOUBLE;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR___REPRESENTABLE_PERIOD__DOUBLE = SUBSUMPTION_LINK___REPRESENTABLE_PERIOD__DOUBLE;

	/**
	 * The number of operations of the '<em>Suppressor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPPRESSOR_OPERATION_COUNT = SUBSUMPTION_LINK_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.DeviceImpl <em>Device</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.DeviceImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getDevice()
	 * @generated
	 */
	int DEVICE = 16;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE__TIME_UNIT = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Kind</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE__KIND = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Data Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE__DATA_TYPE = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Period</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE__PERIOD = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The number of structural features of the '<em>Device</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE___TO_MILLISECONDS__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 1;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE___REPRESENTABLE__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 2;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE___REPRESENTABLE_PERIOD__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 3;

	/**
	 * The number of operations of the '<em>Device</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DEVICE_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 4;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.SensorImpl <em>Sensor</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.SensorImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getSensor()
	 * @generated
	 */
	int SENSOR = 17;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR__NAME = DEVICE__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR__DESCRIPTION = DEVICE__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR__TIME_UNIT = DEVICE__TIME_UNIT;

	/**
	 * The feature id for the '<em><b>Kind</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR__KIND = DEVICE__KIND;

	/**
	 * The feature id for the '<em><b>Data Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR__DATA_TYPE = DEVICE__DATA_TYPE;

	/**
	 * The feature id for the '<em><b>Period</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR__PERIOD = DEVICE__PERIOD;

	/**
	 * The feature id for the '<em><b>Architecture</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR__ARCHITECTURE = DEVICE_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Modules</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR__MODULES = DEVICE_FEATURE_COUNT + 1;

	/**
	 * The number of structural features of the '<em>Sensor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR_FEATURE_COUNT = DEVICE_FEATURE_COUNT + 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR___NORMALIZED_NAME = DEVICE___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR___TO_MILLISECONDS__DOUBLE = DEVICE___TO_MILLISECONDS__DOUBLE;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = DEVICE___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR___REPRESENTABLE__DOUBLE = DEVICE___REPRESENTABLE__DOUBLE;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR___REPRESENTABLE_PERIOD__DOUBLE = DEVICE___REPRESENTABLE_PERIOD__DOUBLE;

	/**
	 * The number of operations of the '<em>Sensor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SENSOR_OPERATION_COUNT = DEVICE_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.ActuatorImpl <em>Actuator</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.ActuatorImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getActuator()
	 * @generated
	 */
	int ACTUATOR = 18;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR__NAME = DEVICE__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR__DESCRIPTION = DEVICE__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR__TIME_UNIT = DEVICE__TIME_UNIT;

	/**
	 * The feature id for the '<em><b>Kind</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR__KIND = DEVICE__KIND;

	/**
	 * The feature id for the '<em><b>Data Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR__DATA_TYPE = DEVICE__DATA_TYPE;

	/**
	 * The feature id for the '<em><b>Period</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR__PERIOD = DEVICE__PERIOD;

	/**
	 * The feature id for the '<em><b>Architecture</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR__ARCHITECTURE = DEVICE_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Modules</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR__MODULES = DEVICE_FEATURE_COUNT + 1;

	/**
	 * The number of structural features of the '<em>Actuator</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR_FEATURE_COUNT = DEVICE_FEATURE_COUNT + 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR___NORMALIZED_NAME = DEVICE___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR___TO_MILLISECONDS__DOUBLE = DEVICE___TO_MILLISECONDS__DOUBLE;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = DEVICE___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR___REPRESENTABLE__DOUBLE = DEVICE___REPRESENTABLE__DOUBLE;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR___REPRESENTABLE_PERIOD__DOUBLE = DEVICE___REPRESENTABLE_PERIOD__DOUBLE;

	/**
	 * The number of operations of the '<em>Actuator</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTUATOR_OPERATION_COUNT = DEVICE_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.MissionImpl <em>Mission</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.MissionImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getMission()
	 * @generated
	 */
	int MISSION = 19;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MISSION__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MISSION__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Architecture</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MISSION__ARCHITECTURE = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Goals</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MISSION__GOALS = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Plans</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MISSION__PLANS = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The number of structural features of the '<em>Mission</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MISSION_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MISSION___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The number of operations of the '<em>Mission</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int MISSION_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.GoalImpl <em>Goal</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.GoalImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getGoal()
	 * @generated
	 */
	int GOAL = 20;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int GOAL__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int GOAL__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Mission</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int GOAL__MISSION = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Parent Goal</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int GOAL__PARENT_GOAL = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Sub Goals</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int GOAL__SUB_GOALS = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Priority</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int GOAL__PRIORITY = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The number of structural features of the '<em>Goal</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int GOAL_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int GOAL___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The number of operations of the '<em>Goal</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int GOAL_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.PlanImpl <em>Plan</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.PlanImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getPlan()
	 * @generated
	 */
	int PLAN = 21;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PLAN__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PLAN__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Mission</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PLAN__MISSION = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Activities</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PLAN__ACTIVITIES = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Achieves</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PLAN__ACHIEVES = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The number of structural features of the '<em>Plan</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PLAN_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PLAN___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The number of operations of the '<em>Plan</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PLAN_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.ActivityImpl <em>Activity</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.ActivityImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getActivity()
	 * @generated
	 */
	int ACTIVITY = 22;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__NAME = REAL_TIME_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__DESCRIPTION = REAL_TIME_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__TIME_UNIT = REAL_TIME_ELEMENT__TIME_UNIT;

	/**
	 * The feature id for the '<em><b>Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__TYPE = REAL_TIME_ELEMENT__TYPE;

	/**
	 * The feature id for the '<em><b>Period</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__PERIOD = REAL_TIME_ELEMENT__PERIOD;

	/**
	 * The feature id for the '<em><b>Delay</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__DELAY = REAL_TIME_ELEMENT__DELAY;

	/**
	 * The feature id for the '<em><b>Exec Duration</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__EXEC_DURATION = REAL_TIME_ELEMENT__EXEC_DURATION;

	/**
	 * The feature id for the '<em><b>Exec Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__EXEC_TYPE = REAL_TIME_ELEMENT__EXEC_TYPE;

	/**
	 * The feature id for the '<em><b>Plan</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__PLAN = REAL_TIME_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Actions</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY__ACTIONS = REAL_TIME_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The number of structural features of the '<em>Activity</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY_FEATURE_COUNT = REAL_TIME_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY___NORMALIZED_NAME = REAL_TIME_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY___TO_MILLISECONDS__DOUBLE = REAL_TIME_ELEMENT___TO_MILLISECONDS__DOUBLE;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = REAL_TIME_ELEMENT___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY___REPRESENTABLE__DOUBLE = REAL_TIME_ELEMENT___REPRESENTABLE__DOUBLE;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY___REPRESENTABLE_PERIOD__DOUBLE = REAL_TIME_ELEMENT___REPRESENTABLE_PERIOD__DOUBLE;

	/**
	 * The number of operations of the '<em>Activity</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ACTIVITY_OPERATION_COUNT = REAL_TIME_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.SupervisorImpl <em>Supervisor</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.SupervisorImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getSupervisor()
	 * @generated
	 */
	int SUPERVISOR = 23;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPERVISOR__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPERVISOR__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Architecture</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPERVISOR__ARCHITECTURE = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Plans</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPERVISOR__PLANS = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Realised By</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPERVISOR__REALISED_BY = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The number of structural features of the '<em>Supervisor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPERVISOR_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPERVISOR___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The number of operations of the '<em>Supervisor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int SUPERVISOR_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.OrderImpl <em>Order</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.OrderImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getOrder()
	 * @generated
	 */
	int ORDER = 24;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ORDER__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ORDER__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Architecture</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ORDER__ARCHITECTURE = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Issuer</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ORDER__ISSUER = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Receiver</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ORDER__RECEIVER = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Requests</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ORDER__REQUESTS = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The number of structural features of the '<em>Order</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ORDER_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ORDER___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The number of operations of the '<em>Order</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int ORDER_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.DatabaseImpl <em>Database</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.DatabaseImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getDatabase()
	 * @generated
	 */
	int DATABASE = 25;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DATABASE__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DATABASE__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Architecture</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DATABASE__ARCHITECTURE = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Knowledge</b></em>' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DATABASE__KNOWLEDGE = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The number of structural features of the '<em>Database</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DATABASE_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DATABASE___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The number of operations of the '<em>Database</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int DATABASE_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.KnowledgeImpl <em>Knowledge</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.KnowledgeImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getKnowledge()
	 * @generated
	 */
	int KNOWLEDGE = 26;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int KNOWLEDGE__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int KNOWLEDGE__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Database</b></em>' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int KNOWLEDGE__DATABASE = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Data Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int KNOWLEDGE__DATA_TYPE = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Used By</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int KNOWLEDGE__USED_BY = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The number of structural features of the '<em>Knowledge</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int KNOWLEDGE_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int KNOWLEDGE___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The number of operations of the '<em>Knowledge</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int KNOWLEDGE_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.ProcessorImpl <em>Processor</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.ProcessorImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getProcessor()
	 * @generated
	 */
	int PROCESSOR = 27;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR__TIME_UNIT = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Sched Policy</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR__SCHED_POLICY = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Core</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR__CORE = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Modules</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR__MODULES = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The feature id for the '<em><b>Host</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR__HOST = NAMED_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The feature id for the '<em><b>Link Latency</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR__LINK_LATENCY = NAMED_ELEMENT_FEATURE_COUNT + 5;

	/**
	 * The number of structural features of the '<em>Processor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 6;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR___TO_MILLISECONDS__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 1;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR___REPRESENTABLE__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 2;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR___REPRESENTABLE_PERIOD__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 3;

	/**
	 * The operation id for the '<em>Package Problem</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR___PACKAGE_PROBLEM = NAMED_ELEMENT_OPERATION_COUNT + 4;

	/**
	 * The number of operations of the '<em>Processor</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int PROCESSOR_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 5;

	/**
	 * The meta object id for the '{@link org.rsaml.model.impl.LatencyRequirementImpl <em>Latency Requirement</em>}' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.impl.LatencyRequirementImpl
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getLatencyRequirement()
	 * @generated
	 */
	int LATENCY_REQUIREMENT = 28;

	/**
	 * The feature id for the '<em><b>Name</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT__NAME = NAMED_ELEMENT__NAME;

	/**
	 * The feature id for the '<em><b>Description</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT__DESCRIPTION = NAMED_ELEMENT__DESCRIPTION;

	/**
	 * The feature id for the '<em><b>Time Unit</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT__TIME_UNIT = NAMED_ELEMENT_FEATURE_COUNT + 0;

	/**
	 * The feature id for the '<em><b>Source</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT__SOURCE = NAMED_ELEMENT_FEATURE_COUNT + 1;

	/**
	 * The feature id for the '<em><b>Target</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT__TARGET = NAMED_ELEMENT_FEATURE_COUNT + 2;

	/**
	 * The feature id for the '<em><b>Max Latency</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT__MAX_LATENCY = NAMED_ELEMENT_FEATURE_COUNT + 3;

	/**
	 * The feature id for the '<em><b>Kind</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT__KIND = NAMED_ELEMENT_FEATURE_COUNT + 4;

	/**
	 * The feature id for the '<em><b>Via</b></em>' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT__VIA = NAMED_ELEMENT_FEATURE_COUNT + 5;

	/**
	 * The number of structural features of the '<em>Latency Requirement</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT_FEATURE_COUNT = NAMED_ELEMENT_FEATURE_COUNT + 6;

	/**
	 * The operation id for the '<em>Normalized Name</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT___NORMALIZED_NAME = NAMED_ELEMENT___NORMALIZED_NAME;

	/**
	 * The operation id for the '<em>To Milliseconds</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT___TO_MILLISECONDS__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 0;

	/**
	 * The operation id for the '<em>Compare Time</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 1;

	/**
	 * The operation id for the '<em>Representable</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT___REPRESENTABLE__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 2;

	/**
	 * The operation id for the '<em>Representable Period</em>' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT___REPRESENTABLE_PERIOD__DOUBLE = NAMED_ELEMENT_OPERATION_COUNT + 3;

	/**
	 * The number of operations of the '<em>Latency Requirement</em>' class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	int LATENCY_REQUIREMENT_OPERATION_COUNT = NAMED_ELEMENT_OPERATION_COUNT + 4;

	/**
	 * The meta object id for the '{@link org.rsaml.model.ArchitectureCategory <em>Architecture Category</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.ArchitectureCategory
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getArchitectureCategory()
	 * @generated
	 */
	int ARCHITECTURE_CATEGORY = 29;

	/**
	 * The meta object id for the '{@link org.rsaml.model.ElementType <em>Element Type</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.ElementType
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getElementType()
	 * @generated
	 */
	int ELEMENT_TYPE = 30;

	/**
	 * The meta object id for the '{@link org.rsaml.model.ExecutionType <em>Execution Type</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.ExecutionType
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getExecutionType()
	 * @generated
	 */
	int EXECUTION_TYPE = 31;

	/**
	 * The meta object id for the '{@link org.rsaml.model.TimeUnit <em>Time Unit</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.TimeUnit
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getTimeUnit()
	 * @generated
	 */
	int TIME_UNIT = 32;

	/**
	 * The meta object id for the '{@link org.rsaml.model.SynchronisationType <em>Synchronisation Type</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.SynchronisationType
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getSynchronisationType()
	 * @generated
	 */
	int SYNCHRONISATION_TYPE = 33;

	/**
	 * The meta object id for the '{@link org.rsaml.model.SchedulingPolicy <em>Scheduling Policy</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.SchedulingPolicy
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getSchedulingPolicy()
	 * @generated
	 */
	int SCHEDULING_POLICY = 34;

	/**
	 * The meta object id for the '{@link org.rsaml.model.DataType <em>Data Type</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.DataType
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getDataType()
	 * @generated
	 */
	int DATA_TYPE = 35;

	/**
	 * The meta object id for the '{@link org.rsaml.model.NodeLifecycle <em>Node Lifecycle</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.NodeLifecycle
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getNodeLifecycle()
	 * @generated
	 */
	int NODE_LIFECYCLE = 36;

	/**
	 * The meta object id for the '{@link org.rsaml.model.PackageLayout <em>Package Layout</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.PackageLayout
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getPackageLayout()
	 * @generated
	 */
	int PACKAGE_LAYOUT = 37;

	/**
	 * The meta object id for the '{@link org.rsaml.model.LatencyKind <em>Latency Kind</em>}' enum.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.rsaml.model.LatencyKind
	 * @see org.rsaml.model.impl.RsamlPackageImpl#getLatencyKind()
	 * @generated
	 */
	int LATENCY_KIND = 38;


	/**
	 * Returns the meta object for class '{@link org.rsaml.model.NamedElement <em>Named Element</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Named Element</em>'.
	 * @see org.rsaml.model.NamedElement
	 * @generated
	 */
	EClass getNamedElement();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.NamedElement#getName <em>Name</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Name</em>'.
	 * @see org.rsaml.model.NamedElement#getName()
	 * @see #getNamedElement()
	 * @generated
	 */
	EAttribute getNamedElement_Name();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.NamedElement#getDescription <em>Description</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Description</em>'.
	 * @see org.rsaml.model.NamedElement#getDescription()
	 * @see #getNamedElement()
	 * @generated
	 */
	EAttribute getNamedElement_Description();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.NamedElement#normalizedName() <em>Normalized Name</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>Normalized Name</em>' operation.
	 * @see org.rsaml.model.NamedElement#normalizedName()
	 * @generated
	 */
	EOperation getNamedElement__NormalizedName();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.TimeScaled <em>Time Scaled</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Time Scaled</em>'.
	 * @see org.rsaml.model.TimeScaled
	 * @generated
	 */
	EClass getTimeScaled();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.TimeScaled#getTimeUnit <em>Time Unit</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Time Unit</em>'.
	 * @see org.rsaml.model.TimeScaled#getTimeUnit()
	 * @see #getTimeScaled()
	 * @generated
	 */
	EAttribute getTimeScaled_TimeUnit();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.TimeScaled#toMilliseconds(double) <em>To Milliseconds</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>To Milliseconds</em>' operation.
	 * @see org.rsaml.model.TimeScaled#toMilliseconds(double)
	 * @generated
	 */
	EOperation getTimeScaled__ToMilliseconds__double();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.TimeScaled#compareTime(double, org.rsaml.model.TimeScaled, double) <em>Compare Time</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>Compare Time</em>' operation.
	 * @see org.rsaml.model.TimeScaled#compareTime(double, org.rsaml.model.TimeScaled, double)
	 * @generated
	 */
	EOperation getTimeScaled__CompareTime__double_TimeScaled_double();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.TimeScaled#representable(double) <em>Representable</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>Representable</em>' operation.
	 * @see org.rsaml.model.TimeScaled#representable(double)
	 * @generated
	 */
	EOperation getTimeScaled__Representable__double();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.TimeScaled#representablePeriod(double) <em>Representable Period</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>Representable Period</em>' operation.
	 * @see org.rsaml.model.TimeScaled#representablePeriod(double)
	 * @generated
	 */
	EOperation getTimeScaled__RepresentablePeriod__double();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.RealTimeElement <em>Real Time Element</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Real Time Element</em>'.
	 * @see org.rsaml.model.RealTimeElement
	 * @generated
	 */
	EClass getRealTimeElement();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.RealTimeElement#getType <em>Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Type</em>'.
	 * @see org.rsaml.model.RealTimeElement#getType()
	 * @see #getRealTimeElement()
	 * @generated
	 */
	EAttribute getRealTimeElement_Type();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.RealTimeElement#getPeriod <em>Period</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Period</em>'.
	 * @see org.rsaml.model.RealTimeElement#getPeriod()
	 * @see #getRealTimeElement()
	 * @generated
	 */
	EAttribute getRealTimeElement_Period();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.RealTimeElement#getDelay <em>Delay</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Delay</em>'.
	 * @see org.rsaml.model.RealTimeElement#getDelay()
	 * @see #getRealTimeElement()
	 * @generated
	 */
	EAttribute getRealTimeElement_Delay();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.RealTimeElement#getExecDuration <em>Exec Duration</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Exec Duration</em>'.
	 * @see org.rsaml.model.RealTimeElement#getExecDuration()
	 * @see #getRealTimeElement()
	 * @generated
	 */
	EAttribute getRealTimeElement_ExecDuration();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.RealTimeElement#getExecType <em>Exec Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Exec Type</em>'.
	 * @see org.rsaml.model.RealTimeElement#getExecType()
	 * @see #getRealTimeElement()
	 * @generated
	 */
	EAttribute getRealTimeElement_ExecType();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Architecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Architecture</em>'.
	 * @see org.rsaml.model.Architecture
	 * @generated
	 */
	EClass getArchitecture();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Architecture#getCategory <em>Category</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Category</em>'.
	 * @see org.rsaml.model.Architecture#getCategory()
	 * @see #getArchitecture()
	 * @generated
	 */
	EAttribute getArchitecture_Category();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Architecture#getDeclaredLayers <em>Declared Layers</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Declared Layers</em>'.
	 * @see org.rsaml.model.Architecture#getDeclaredLayers()
	 * @see #getArchitecture()
	 * @generated
	 */
	EAttribute getArchitecture_DeclaredLayers();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Architecture#getLifecycle <em>Lifecycle</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Lifecycle</em>'.
	 * @see org.rsaml.model.Architecture#getLifecycle()
	 * @see #getArchitecture()
	 * @generated
	 */
	EAttribute getArchitecture_Lifecycle();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Architecture#getPackages <em>Packages</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Packages</em>'.
	 * @see org.rsaml.model.Architecture#getPackages()
	 * @see #getArchitecture()
	 * @generated
	 */
	EAttribute getArchitecture_Packages();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getLayers <em>Layers</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Layers</em>'.
	 * @see org.rsaml.model.Architecture#getLayers()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_Layers();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getConnections <em>Connections</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Connections</em>'.
	 * @see org.rsaml.model.Architecture#getConnections()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_Connections();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getSensors <em>Sensors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Sensors</em>'.
	 * @see org.rsaml.model.Architecture#getSensors()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_Sensors();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getActuators <em>Actuators</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Actuators</em>'.
	 * @see org.rsaml.model.Architecture#getActuators()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_Actuators();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getMissions <em>Missions</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Missions</em>'.
	 * @see org.rsaml.model.Architecture#getMissions()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_Missions();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getSupervisors <em>Supervisors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Supervisors</em>'.
	 * @see org.rsaml.model.Architecture#getSupervisors()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_Supervisors();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getOrders <em>Orders</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Orders</em>'.
	 * @see org.rsaml.model.Architecture#getOrders()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_Orders();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getDatabases <em>Databases</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Databases</em>'.
	 * @see org.rsaml.model.Architecture#getDatabases()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_Databases();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getProcessors <em>Processors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Processors</em>'.
	 * @see org.rsaml.model.Architecture#getProcessors()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_Processors();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Architecture#getLatencyRequirements <em>Latency Requirements</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Latency Requirements</em>'.
	 * @see org.rsaml.model.Architecture#getLatencyRequirements()
	 * @see #getArchitecture()
	 * @generated
	 */
	EReference getArchitecture_LatencyRequirements();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Layer <em>Layer</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Layer</em>'.
	 * @see org.rsaml.model.Layer
	 * @generated
	 */
	EClass getLayer();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Layer#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Architecture</em>'.
	 * @see org.rsaml.model.Layer#getArchitecture()
	 * @see #getLayer()
	 * @generated
	 */
	EReference getLayer_Architecture();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Layer#getLevel <em>Level</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Level</em>'.
	 * @see org.rsaml.model.Layer#getLevel()
	 * @see #getLayer()
	 * @generated
	 */
	EAttribute getLayer_Level();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Layer#getMaxExecTime <em>Max Exec Time</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Max Exec Time</em>'.
	 * @see org.rsaml.model.Layer#getMaxExecTime()
	 * @see #getLayer()
	 * @generated
	 */
	EAttribute getLayer_MaxExecTime();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Layer#getModules <em>Modules</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Modules</em>'.
	 * @see org.rsaml.model.Layer#getModules()
	 * @see #getLayer()
	 * @generated
	 */
	EReference getLayer_Modules();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.Layer#packageProblem() <em>Package Problem</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>Package Problem</em>' operation.
	 * @see org.rsaml.model.Layer#packageProblem()
	 * @generated
	 */
	EOperation getLayer__PackageProblem();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Module <em>Module</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Module</em>'.
	 * @see org.rsaml.model.Module
	 * @generated
	 */
	EClass getModule();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Module#getLayer <em>Layer</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Layer</em>'.
	 * @see org.rsaml.model.Module#getLayer()
	 * @see #getModule()
	 * @generated
	 */
	EReference getModule_Layer();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Module#getFunctions <em>Functions</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Functions</em>'.
	 * @see org.rsaml.model.Module#getFunctions()
	 * @see #getModule()
	 * @generated
	 */
	EReference getModule_Functions();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Module#getPorts <em>Ports</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Ports</em>'.
	 * @see org.rsaml.model.Module#getPorts()
	 * @see #getModule()
	 * @generated
	 */
	EReference getModule_Ports();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Module#getInhibitors <em>Inhibitors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Inhibitors</em>'.
	 * @see org.rsaml.model.Module#getInhibitors()
	 * @see #getModule()
	 * @generated
	 */
	EReference getModule_Inhibitors();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Module#getSuppressors <em>Suppressors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Suppressors</em>'.
	 * @see org.rsaml.model.Module#getSuppressors()
	 * @see #getModule()
	 * @generated
	 */
	EReference getModule_Suppressors();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.Module#getSensors <em>Sensors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Sensors</em>'.
	 * @see org.rsaml.model.Module#getSensors()
	 * @see #getModule()
	 * @generated
	 */
	EReference getModule_Sensors();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.Module#getActuators <em>Actuators</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Actuators</em>'.
	 * @see org.rsaml.model.Module#getActuators()
	 * @see #getModule()
	 * @generated
	 */
	EReference getModule_Actuators();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Module#getLifecycle <em>Lifecycle</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Lifecycle</em>'.
	 * @see org.rsaml.model.Module#getLifecycle()
	 * @see #getModule()
	 * @generated
	 */
	EAttribute getModule_Lifecycle();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.Module#effectiveLifecycle() <em>Effective Lifecycle</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>Effective Lifecycle</em>' operation.
	 * @see org.rsaml.model.Module#effectiveLifecycle()
	 * @generated
	 */
	EOperation getModule__EffectiveLifecycle();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Function <em>Function</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Function</em>'.
	 * @see org.rsaml.model.Function
	 * @generated
	 */
	EClass getFunction();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Function#getModule <em>Module</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Module</em>'.
	 * @see org.rsaml.model.Function#getModule()
	 * @see #getFunction()
	 * @generated
	 */
	EReference getFunction_Module();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Function#getActions <em>Actions</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Actions</em>'.
	 * @see org.rsaml.model.Function#getActions()
	 * @see #getFunction()
	 * @generated
	 */
	EReference getFunction_Actions();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Function#getSynchroType <em>Synchro Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Synchro Type</em>'.
	 * @see org.rsaml.model.Function#getSynchroType()
	 * @see #getFunction()
	 * @generated
	 */
	EAttribute getFunction_SynchroType();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Function#getSchedPolicy <em>Sched Policy</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Sched Policy</em>'.
	 * @see org.rsaml.model.Function#getSchedPolicy()
	 * @see #getFunction()
	 * @generated
	 */
	EAttribute getFunction_SchedPolicy();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Function#getOtherPolicy <em>Other Policy</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Other Policy</em>'.
	 * @see org.rsaml.model.Function#getOtherPolicy()
	 * @see #getFunction()
	 * @generated
	 */
	EAttribute getFunction_OtherPolicy();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Action <em>Action</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Action</em>'.
	 * @see org.rsaml.model.Action
	 * @generated
	 */
	EClass getAction();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Action#getFunction <em>Function</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Function</em>'.
	 * @see org.rsaml.model.Action#getFunction()
	 * @see #getAction()
	 * @generated
	 */
	EReference getAction_Function();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Action#getStartDate <em>Start Date</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Start Date</em>'.
	 * @see org.rsaml.model.Action#getStartDate()
	 * @see #getAction()
	 * @generated
	 */
	EAttribute getAction_StartDate();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.RTAction <em>RT Action</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>RT Action</em>'.
	 * @see org.rsaml.model.RTAction
	 * @generated
	 */
	EClass getRTAction();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Port <em>Port</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Port</em>'.
	 * @see org.rsaml.model.Port
	 * @generated
	 */
	EClass getPort();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Port#getModule <em>Module</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Module</em>'.
	 * @see org.rsaml.model.Port#getModule()
	 * @see #getPort()
	 * @generated
	 */
	EReference getPort_Module();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Port#getDataType <em>Data Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Data Type</em>'.
	 * @see org.rsaml.model.Port#getDataType()
	 * @see #getPort()
	 * @generated
	 */
	EAttribute getPort_DataType();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Port#getMessageType <em>Message Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Message Type</em>'.
	 * @see org.rsaml.model.Port#getMessageType()
	 * @see #getPort()
	 * @generated
	 */
	EAttribute getPort_MessageType();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Port#getTopic <em>Topic</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Topic</em>'.
	 * @see org.rsaml.model.Port#getTopic()
	 * @see #getPort()
	 * @generated
	 */
	EAttribute getPort_Topic();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.Port#normalizedMessageType() <em>Normalized Message Type</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>Normalized Message Type</em>' operation.
	 * @see org.rsaml.model.Port#normalizedMessageType()
	 * @generated
	 */
	EOperation getPort__NormalizedMessageType();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.Port#topicProblem() <em>Topic Problem</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>Topic Problem</em>' operation.
	 * @see org.rsaml.model.Port#topicProblem()
	 * @generated
	 */
	EOperation getPort__TopicProblem();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.EntryPort <em>Entry Port</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Entry Port</em>'.
	 * @see org.rsaml.model.EntryPort
	 * @generated
	 */
	EClass getEntryPort();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.EntryPort#getIncoming <em>Incoming</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Incoming</em>'.
	 * @see org.rsaml.model.EntryPort#getIncoming()
	 * @see #getEntryPort()
	 * @generated
	 */
	EReference getEntryPort_Incoming();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.EntryPort#getSuppressedBy <em>Suppressed By</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Suppressed By</em>'.
	 * @see org.rsaml.model.EntryPort#getSuppressedBy()
	 * @see #getEntryPort()
	 * @generated
	 */
	EReference getEntryPort_SuppressedBy();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.OutputPort <em>Output Port</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Output Port</em>'.
	 * @see org.rsaml.model.OutputPort
	 * @generated
	 */
	EClass getOutputPort();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.OutputPort#getOutgoing <em>Outgoing</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Outgoing</em>'.
	 * @see org.rsaml.model.OutputPort#getOutgoing()
	 * @see #getOutputPort()
	 * @generated
	 */
	EReference getOutputPort_Outgoing();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.OutputPort#getInhibitedBy <em>Inhibited By</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Inhibited By</em>'.
	 * @see org.rsaml.model.OutputPort#getInhibitedBy()
	 * @see #getOutputPort()
	 * @generated
	 */
	EReference getOutputPort_InhibitedBy();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Connection <em>Connection</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Connection</em>'.
	 * @see org.rsaml.model.Connection
	 * @generated
	 */
	EClass getConnection();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Connection#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Architecture</em>'.
	 * @see org.rsaml.model.Connection#getArchitecture()
	 * @see #getConnection()
	 * @generated
	 */
	EReference getConnection_Architecture();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.Connection#getSource <em>Source</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Source</em>'.
	 * @see org.rsaml.model.Connection#getSource()
	 * @see #getConnection()
	 * @generated
	 */
	EReference getConnection_Source();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.Connection#getTarget <em>Target</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Target</em>'.
	 * @see org.rsaml.model.Connection#getTarget()
	 * @see #getConnection()
	 * @generated
	 */
	EReference getConnection_Target();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.SubsumptionLink <em>Subsumption Link</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Subsumption Link</em>'.
	 * @see org.rsaml.model.SubsumptionLink
	 * @generated
	 */
	EClass getSubsumptionLink();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.SubsumptionLink#getTrigger <em>Trigger</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Trigger</em>'.
	 * @see org.rsaml.model.SubsumptionLink#getTrigger()
	 * @see #getSubsumptionLink()
	 * @generated
	 */
	EReference getSubsumptionLink_Trigger();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.SubsumptionLink#getDuration <em>Duration</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Duration</em>'.
	 * @see org.rsaml.model.SubsumptionLink#getDuration()
	 * @see #getSubsumptionLink()
	 * @generated
	 */
	EAttribute getSubsumptionLink_Duration();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Inhibitor <em>Inhibitor</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Inhibitor</em>'.
	 * @see org.rsaml.model.Inhibitor
	 * @generated
	 */
	EClass getInhibitor();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Inhibitor#getModule <em>Module</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Module</em>'.
	 * @see org.rsaml.model.Inhibitor#getModule()
	 * @see #getInhibitor()
	 * @generated
	 */
	EReference getInhibitor_Module();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.Inhibitor#getTarget <em>Target</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Target</em>'.
	 * @see org.rsaml.model.Inhibitor#getTarget()
	 * @see #getInhibitor()
	 * @generated
	 */
	EReference getInhibitor_Target();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Suppressor <em>Suppressor</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Suppressor</em>'.
	 * @see org.rsaml.model.Suppressor
	 * @generated
	 */
	EClass getSuppressor();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Suppressor#getModule <em>Module</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Module</em>'.
	 * @see org.rsaml.model.Suppressor#getModule()
	 * @see #getSuppressor()
	 * @generated
	 */
	EReference getSuppressor_Module();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.Suppressor#getTarget <em>Target</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Target</em>'.
	 * @see org.rsaml.model.Suppressor#getTarget()
	 * @see #getSuppressor()
	 * @generated
	 */
	EReference getSuppressor_Target();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Device <em>Device</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Device</em>'.
	 * @see org.rsaml.model.Device
	 * @generated
	 */
	EClass getDevice();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Device#getKind <em>Kind</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Kind</em>'.
	 * @see org.rsaml.model.Device#getKind()
	 * @see #getDevice()
	 * @generated
	 */
	EAttribute getDevice_Kind();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Device#getDataType <em>Data Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Data Type</em>'.
	 * @see org.rsaml.model.Device#getDataType()
	 * @see #getDevice()
	 * @generated
	 */
	EAttribute getDevice_DataType();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Device#getPeriod <em>Period</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Period</em>'.
	 * @see org.rsaml.model.Device#getPeriod()
	 * @see #getDevice()
	 * @generated
	 */
	EAttribute getDevice_Period();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Sensor <em>Sensor</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Sensor</em>'.
	 * @see org.rsaml.model.Sensor
	 * @generated
	 */
	EClass getSensor();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Sensor#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Architecture</em>'.
	 * @see org.rsaml.model.Sensor#getArchitecture()
	 * @see #getSensor()
	 * @generated
	 */
	EReference getSensor_Architecture();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.Sensor#getModules <em>Modules</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Modules</em>'.
	 * @see org.rsaml.model.Sensor#getModules()
	 * @see #getSensor()
	 * @generated
	 */
	EReference getSensor_Modules();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Actuator <em>Actuator</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Actuator</em>'.
	 * @see org.rsaml.model.Actuator
	 * @generated
	 */
	EClass getActuator();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Actuator#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Architecture</em>'.
	 * @see org.rsaml.model.Actuator#getArchitecture()
	 * @see #getActuator()
	 * @generated
	 */
	EReference getActuator_Architecture();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.Actuator#getModules <em>Modules</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Modules</em>'.
	 * @see org.rsaml.model.Actuator#getModules()
	 * @see #getActuator()
	 * @generated
	 */
	EReference getActuator_Modules();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Mission <em>Mission</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Mission</em>'.
	 * @see org.rsaml.model.Mission
	 * @generated
	 */
	EClass getMission();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Mission#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Architecture</em>'.
	 * @see org.rsaml.model.Mission#getArchitecture()
	 * @see #getMission()
	 * @generated
	 */
	EReference getMission_Architecture();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Mission#getGoals <em>Goals</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Goals</em>'.
	 * @see org.rsaml.model.Mission#getGoals()
	 * @see #getMission()
	 * @generated
	 */
	EReference getMission_Goals();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Mission#getPlans <em>Plans</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Plans</em>'.
	 * @see org.rsaml.model.Mission#getPlans()
	 * @see #getMission()
	 * @generated
	 */
	EReference getMission_Plans();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Goal <em>Goal</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Goal</em>'.
	 * @see org.rsaml.model.Goal
	 * @generated
	 */
	EClass getGoal();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Goal#getMission <em>Mission</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Mission</em>'.
	 * @see org.rsaml.model.Goal#getMission()
	 * @see #getGoal()
	 * @generated
	 */
	EReference getGoal_Mission();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Goal#getParentGoal <em>Parent Goal</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Parent Goal</em>'.
	 * @see org.rsaml.model.Goal#getParentGoal()
	 * @see #getGoal()
	 * @generated
	 */
	EReference getGoal_ParentGoal();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Goal#getSubGoals <em>Sub Goals</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Sub Goals</em>'.
	 * @see org.rsaml.model.Goal#getSubGoals()
	 * @see #getGoal()
	 * @generated
	 */
	EReference getGoal_SubGoals();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Goal#getPriority <em>Priority</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Priority</em>'.
	 * @see org.rsaml.model.Goal#getPriority()
	 * @see #getGoal()
	 * @generated
	 */
	EAttribute getGoal_Priority();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Plan <em>Plan</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Plan</em>'.
	 * @see org.rsaml.model.Plan
	 * @generated
	 */
	EClass getPlan();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Plan#getMission <em>Mission</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Mission</em>'.
	 * @see org.rsaml.model.Plan#getMission()
	 * @see #getPlan()
	 * @generated
	 */
	EReference getPlan_Mission();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Plan#getActivities <em>Activities</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Activities</em>'.
	 * @see org.rsaml.model.Plan#getActivities()
	 * @see #getPlan()
	 * @generated
	 */
	EReference getPlan_Activities();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.Plan#getAchieves <em>Achieves</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Achieves</em>'.
	 * @see org.rsaml.model.Plan#getAchieves()
	 * @see #getPlan()
	 * @generated
	 */
	EReference getPlan_Achieves();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Activity <em>Activity</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Activity</em>'.
	 * @see org.rsaml.model.Activity
	 * @generated
	 */
	EClass getActivity();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Activity#getPlan <em>Plan</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Plan</em>'.
	 * @see org.rsaml.model.Activity#getPlan()
	 * @see #getActivity()
	 * @generated
	 */
	EReference getActivity_Plan();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.Activity#getActions <em>Actions</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Actions</em>'.
	 * @see org.rsaml.model.Activity#getActions()
	 * @see #getActivity()
	 * @generated
	 */
	EReference getActivity_Actions();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Supervisor <em>Supervisor</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Supervisor</em>'.
	 * @see org.rsaml.model.Supervisor
	 * @generated
	 */
	EClass getSupervisor();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Supervisor#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Architecture</em>'.
	 * @see org.rsaml.model.Supervisor#getArchitecture()
	 * @see #getSupervisor()
	 * @generated
	 */
	EReference getSupervisor_Architecture();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.Supervisor#getPlans <em>Plans</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Plans</em>'.
	 * @see org.rsaml.model.Supervisor#getPlans()
	 * @see #getSupervisor()
	 * @generated
	 */
	EReference getSupervisor_Plans();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.Supervisor#getRealisedBy <em>Realised By</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Realised By</em>'.
	 * @see org.rsaml.model.Supervisor#getRealisedBy()
	 * @see #getSupervisor()
	 * @generated
	 */
	EReference getSupervisor_RealisedBy();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Order <em>Order</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Order</em>'.
	 * @see org.rsaml.model.Order
	 * @generated
	 */
	EClass getOrder();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Order#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Architecture</em>'.
	 * @see org.rsaml.model.Order#getArchitecture()
	 * @see #getOrder()
	 * @generated
	 */
	EReference getOrder_Architecture();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Order#getIssuer <em>Issuer</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Issuer</em>'.
	 * @see org.rsaml.model.Order#getIssuer()
	 * @see #getOrder()
	 * @generated
	 */
	EAttribute getOrder_Issuer();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.Order#getReceiver <em>Receiver</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Receiver</em>'.
	 * @see org.rsaml.model.Order#getReceiver()
	 * @see #getOrder()
	 * @generated
	 */
	EReference getOrder_Receiver();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.Order#getRequests <em>Requests</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Requests</em>'.
	 * @see org.rsaml.model.Order#getRequests()
	 * @see #getOrder()
	 * @generated
	 */
	EReference getOrder_Requests();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Database <em>Database</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Database</em>'.
	 * @see org.rsaml.model.Database
	 * @generated
	 */
	EClass getDatabase();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Database#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Architecture</em>'.
	 * @see org.rsaml.model.Database#getArchitecture()
	 * @see #getDatabase()
	 * @generated
	 */
	EReference getDatabase_Architecture();

	/**
	 * Returns the meta object for the containment reference list '{@link org.rsaml.model.Database#getKnowledge <em>Knowledge</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the containment reference list '<em>Knowledge</em>'.
	 * @see org.rsaml.model.Database#getKnowledge()
	 * @see #getDatabase()
	 * @generated
	 */
	EReference getDatabase_Knowledge();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Knowledge <em>Knowledge</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Knowledge</em>'.
	 * @see org.rsaml.model.Knowledge
	 * @generated
	 */
	EClass getKnowledge();

	/**
	 * Returns the meta object for the container reference '{@link org.rsaml.model.Knowledge#getDatabase <em>Database</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the container reference '<em>Database</em>'.
	 * @see org.rsaml.model.Knowledge#getDatabase()
	 * @see #getKnowledge()
	 * @generated
	 */
	EReference getKnowledge_Database();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Knowledge#getDataType <em>Data Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Data Type</em>'.
	 * @see org.rsaml.model.Knowledge#getDataType()
	 * @see #getKnowledge()
	 * @generated
	 */
	EAttribute getKnowledge_DataType();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.Knowledge#getUsedBy <em>Used By</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Used By</em>'.
	 * @see org.rsaml.model.Knowledge#getUsedBy()
	 * @see #getKnowledge()
	 * @generated
	 */
	EReference getKnowledge_UsedBy();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.Processor <em>Processor</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Processor</em>'.
	 * @see org.rsaml.model.Processor
	 * @generated
	 */
	EClass getProcessor();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Processor#getSchedPolicy <em>Sched Policy</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Sched Policy</em>'.
	 * @see org.rsaml.model.Processor#getSchedPolicy()
	 * @see #getProcessor()
	 * @generated
	 */
	EAttribute getProcessor_SchedPolicy();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Processor#getCore <em>Core</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Core</em>'.
	 * @see org.rsaml.model.Processor#getCore()
	 * @see #getProcessor()
	 * @generated
	 */
	EAttribute getProcessor_Core();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.Processor#getModules <em>Modules</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Modules</em>'.
	 * @see org.rsaml.model.Processor#getModules()
	 * @see #getProcessor()
	 * @generated
	 */
	EReference getProcessor_Modules();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Processor#getHost <em>Host</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Host</em>'.
	 * @see org.rsaml.model.Processor#getHost()
	 * @see #getProcessor()
	 * @generated
	 */
	EAttribute getProcessor_Host();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.Processor#getLinkLatency <em>Link Latency</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Link Latency</em>'.
	 * @see org.rsaml.model.Processor#getLinkLatency()
	 * @see #getProcessor()
	 * @generated
	 */
	EAttribute getProcessor_LinkLatency();

	/**
	 * Returns the meta object for the '{@link org.rsaml.model.Processor#packageProblem() <em>Package Problem</em>}' operation.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the '<em>Package Problem</em>' operation.
	 * @see org.rsaml.model.Processor#packageProblem()
	 * @generated
	 */
	EOperation getProcessor__PackageProblem();

	/**
	 * Returns the meta object for class '{@link org.rsaml.model.LatencyRequirement <em>Latency Requirement</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for class '<em>Latency Requirement</em>'.
	 * @see org.rsaml.model.LatencyRequirement
	 * @generated
	 */
	EClass getLatencyRequirement();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.LatencyRequirement#getSource <em>Source</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Source</em>'.
	 * @see org.rsaml.model.LatencyRequirement#getSource()
	 * @see #getLatencyRequirement()
	 * @generated
	 */
	EReference getLatencyRequirement_Source();

	/**
	 * Returns the meta object for the reference '{@link org.rsaml.model.LatencyRequirement#getTarget <em>Target</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference '<em>Target</em>'.
	 * @see org.rsaml.model.LatencyRequirement#getTarget()
	 * @see #getLatencyRequirement()
	 * @generated
	 */
	EReference getLatencyRequirement_Target();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.LatencyRequirement#getMaxLatency <em>Max Latency</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Max Latency</em>'.
	 * @see org.rsaml.model.LatencyRequirement#getMaxLatency()
	 * @see #getLatencyRequirement()
	 * @generated
	 */
	EAttribute getLatencyRequirement_MaxLatency();

	/**
	 * Returns the meta object for the attribute '{@link org.rsaml.model.LatencyRequirement#getKind <em>Kind</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the attribute '<em>Kind</em>'.
	 * @see org.rsaml.model.LatencyRequirement#getKind()
	 * @see #getLatencyRequirement()
	 * @generated
	 */
	EAttribute getLatencyRequirement_Kind();

	/**
	 * Returns the meta object for the reference list '{@link org.rsaml.model.LatencyRequirement#getVia <em>Via</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for the reference list '<em>Via</em>'.
	 * @see org.rsaml.model.LatencyRequirement#getVia()
	 * @see #getLatencyRequirement()
	 * @generated
	 */
	EReference getLatencyRequirement_Via();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.ArchitectureCategory <em>Architecture Category</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Architecture Category</em>'.
	 * @see org.rsaml.model.ArchitectureCategory
	 * @generated
	 */
	EEnum getArchitectureCategory();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.ElementType <em>Element Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Element Type</em>'.
	 * @see org.rsaml.model.ElementType
	 * @generated
	 */
	EEnum getElementType();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.ExecutionType <em>Execution Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Execution Type</em>'.
	 * @see org.rsaml.model.ExecutionType
	 * @generated
	 */
	EEnum getExecutionType();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.TimeUnit <em>Time Unit</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Time Unit</em>'.
	 * @see org.rsaml.model.TimeUnit
	 * @generated
	 */
	EEnum getTimeUnit();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.SynchronisationType <em>Synchronisation Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Synchronisation Type</em>'.
	 * @see org.rsaml.model.SynchronisationType
	 * @generated
	 */
	EEnum getSynchronisationType();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.SchedulingPolicy <em>Scheduling Policy</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Scheduling Policy</em>'.
	 * @see org.rsaml.model.SchedulingPolicy
	 * @generated
	 */
	EEnum getSchedulingPolicy();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.DataType <em>Data Type</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Data Type</em>'.
	 * @see org.rsaml.model.DataType
	 * @generated
	 */
	EEnum getDataType();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.NodeLifecycle <em>Node Lifecycle</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Node Lifecycle</em>'.
	 * @see org.rsaml.model.NodeLifecycle
	 * @generated
	 */
	EEnum getNodeLifecycle();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.PackageLayout <em>Package Layout</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Package Layout</em>'.
	 * @see org.rsaml.model.PackageLayout
	 * @generated
	 */
	EEnum getPackageLayout();

	/**
	 * Returns the meta object for enum '{@link org.rsaml.model.LatencyKind <em>Latency Kind</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the meta object for enum '<em>Latency Kind</em>'.
	 * @see org.rsaml.model.LatencyKind
	 * @generated
	 */
	EEnum getLatencyKind();

	/**
	 * Returns the factory that creates the instances of the model.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return the factory that creates the instances of the model.
	 * @generated
	 */
	RsamlFactory getRsamlFactory();

	/**
	 * <!-- begin-user-doc -->
	 * Defines literals for the meta objects that represent
	 * <ul>
	 *   <li>each class,</li>
	 *   <li>each feature of each class,</li>
	 *   <li>each operation of each class,</li>
	 *   <li>each enum,</li>
	 *   <li>and each data type</li>
	 * </ul>
	 * <!-- end-user-doc -->
	 * @generated
	 */
	interface Literals {
		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.NamedElementImpl <em>Named Element</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.NamedElementImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getNamedElement()
		 * @generated
		 */
		EClass NAMED_ELEMENT = eINSTANCE.getNamedElement();

		/**
		 * The meta object literal for the '<em><b>Name</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute NAMED_ELEMENT__NAME = eINSTANCE.getNamedElement_Name();

		/**
		 * The meta object literal for the '<em><b>Description</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute NAMED_ELEMENT__DESCRIPTION = eINSTANCE.getNamedElement_Description();

		/**
		 * The meta object literal for the '<em><b>Normalized Name</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation NAMED_ELEMENT___NORMALIZED_NAME = eINSTANCE.getNamedElement__NormalizedName();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.TimeScaled <em>Time Scaled</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.TimeScaled
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getTimeScaled()
		 * @generated
		 */
		EClass TIME_SCALED = eINSTANCE.getTimeScaled();

		/**
		 * The meta object literal for the '<em><b>Time Unit</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute TIME_SCALED__TIME_UNIT = eINSTANCE.getTimeScaled_TimeUnit();

		/**
		 * The meta object literal for the '<em><b>To Milliseconds</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation TIME_SCALED___TO_MILLISECONDS__DOUBLE = eINSTANCE.getTimeScaled__ToMilliseconds__double();

		/**
		 * The meta object literal for the '<em><b>Compare Time</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation TIME_SCALED___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE = eINSTANCE.getTimeScaled__CompareTime__double_TimeScaled_double();

		/**
		 * The meta object literal for the '<em><b>Representable</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation TIME_SCALED___REPRESENTABLE__DOUBLE = eINSTANCE.getTimeScaled__Representable__double();

		/**
		 * The meta object literal for the '<em><b>Representable Period</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation TIME_SCALED___REPRESENTABLE_PERIOD__DOUBLE = eINSTANCE.getTimeScaled__RepresentablePeriod__double();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.RealTimeElementImpl <em>Real Time Element</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.RealTimeElementImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getRealTimeElement()
		 * @generated
		 */
		EClass REAL_TIME_ELEMENT = eINSTANCE.getRealTimeElement();

		/**
		 * The meta object literal for the '<em><b>Type</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute REAL_TIME_ELEMENT__TYPE = eINSTANCE.getRealTimeElement_Type();

		/**
		 * The meta object literal for the '<em><b>Period</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute REAL_TIME_ELEMENT__PERIOD = eINSTANCE.getRealTimeElement_Period();

		/**
		 * The meta object literal for the '<em><b>Delay</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute REAL_TIME_ELEMENT__DELAY = eINSTANCE.getRealTimeElement_Delay();

		/**
		 * The meta object literal for the '<em><b>Exec Duration</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute REAL_TIME_ELEMENT__EXEC_DURATION = eINSTANCE.getRealTimeElement_ExecDuration();

		/**
		 * The meta object literal for the '<em><b>Exec Type</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute REAL_TIME_ELEMENT__EXEC_TYPE = eINSTANCE.getRealTimeElement_ExecType();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.ArchitectureImpl <em>Architecture</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.ArchitectureImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getArchitecture()
		 * @generated
		 */
		EClass ARCHITECTURE = eINSTANCE.getArchitecture();

		/**
		 * The meta object literal for the '<em><b>Category</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute ARCHITECTURE__CATEGORY = eINSTANCE.getArchitecture_Category();

		/**
		 * The meta object literal for the '<em><b>Declared Layers</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute ARCHITECTURE__DECLARED_LAYERS = eINSTANCE.getArchitecture_DeclaredLayers();

		/**
		 * The meta object literal for the '<em><b>Lifecycle</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute ARCHITECTURE__LIFECYCLE = eINSTANCE.getArchitecture_Lifecycle();

		/**
		 * The meta object literal for the '<em><b>Packages</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute ARCHITECTURE__PACKAGES = eINSTANCE.getArchitecture_Packages();

		/**
		 * The meta object literal for the '<em><b>Layers</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__LAYERS = eINSTANCE.getArchitecture_Layers();

		/**
		 * The meta object literal for the '<em><b>Connections</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__CONNECTIONS = eINSTANCE.getArchitecture_Connections();

		/**
		 * The meta object literal for the '<em><b>Sensors</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__SENSORS = eINSTANCE.getArchitecture_Sensors();

		/**
		 * The meta object literal for the '<em><b>Actuators</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__ACTUATORS = eINSTANCE.getArchitecture_Actuators();

		/**
		 * The meta object literal for the '<em><b>Missions</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__MISSIONS = eINSTANCE.getArchitecture_Missions();

		/**
		 * The meta object literal for the '<em><b>Supervisors</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__SUPERVISORS = eINSTANCE.getArchitecture_Supervisors();

		/**
		 * The meta object literal for the '<em><b>Orders</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__ORDERS = eINSTANCE.getArchitecture_Orders();

		/**
		 * The meta object literal for the '<em><b>Databases</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__DATABASES = eINSTANCE.getArchitecture_Databases();

		/**
		 * The meta object literal for the '<em><b>Processors</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__PROCESSORS = eINSTANCE.getArchitecture_Processors();

		/**
		 * The meta object literal for the '<em><b>Latency Requirements</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ARCHITECTURE__LATENCY_REQUIREMENTS = eINSTANCE.getArchitecture_LatencyRequirements();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.LayerImpl <em>Layer</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.LayerImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getLayer()
		 * @generated
		 */
		EClass LAYER = eINSTANCE.getLayer();

		/**
		 * The meta object literal for the '<em><b>Architecture</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference LAYER__ARCHITECTURE = eINSTANCE.getLayer_Architecture();

		/**
		 * The meta object literal for the '<em><b>Level</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute LAYER__LEVEL = eINSTANCE.getLayer_Level();

		/**
		 * The meta object literal for the '<em><b>Max Exec Time</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute LAYER__MAX_EXEC_TIME = eINSTANCE.getLayer_MaxExecTime();

		/**
		 * The meta object literal for the '<em><b>Modules</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference LAYER__MODULES = eINSTANCE.getLayer_Modules();

		/**
		 * The meta object literal for the '<em><b>Package Problem</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation LAYER___PACKAGE_PROBLEM = eINSTANCE.getLayer__PackageProblem();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.ModuleImpl <em>Module</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.ModuleImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getModule()
		 * @generated
		 */
		EClass MODULE = eINSTANCE.getModule();

		/**
		 * The meta object literal for the '<em><b>Layer</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MODULE__LAYER = eINSTANCE.getModule_Layer();

		/**
		 * The meta object literal for the '<em><b>Functions</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MODULE__FUNCTIONS = eINSTANCE.getModule_Functions();

		/**
		 * The meta object literal for the '<em><b>Ports</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MODULE__PORTS = eINSTANCE.getModule_Ports();

		/**
		 * The meta object literal for the '<em><b>Inhibitors</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MODULE__INHIBITORS = eINSTANCE.getModule_Inhibitors();

		/**
		 * The meta object literal for the '<em><b>Suppressors</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MODULE__SUPPRESSORS = eINSTANCE.getModule_Suppressors();

		/**
		 * The meta object literal for the '<em><b>Sensors</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MODULE__SENSORS = eINSTANCE.getModule_Sensors();

		/**
		 * The meta object literal for the '<em><b>Actuators</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MODULE__ACTUATORS = eINSTANCE.getModule_Actuators();

		/**
		 * The meta object literal for the '<em><b>Lifecycle</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute MODULE__LIFECYCLE = eINSTANCE.getModule_Lifecycle();

		/**
		 * The meta object literal for the '<em><b>Effective Lifecycle</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation MODULE___EFFECTIVE_LIFECYCLE = eINSTANCE.getModule__EffectiveLifecycle();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.FunctionImpl <em>Function</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.FunctionImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getFunction()
		 * @generated
		 */
		EClass FUNCTION = eINSTANCE.getFunction();

		/**
		 * The meta object literal for the '<em><b>Module</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference FUNCTION__MODULE = eINSTANCE.getFunction_Module();

		/**
		 * The meta object literal for the '<em><b>Actions</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference FUNCTION__ACTIONS = eINSTANCE.getFunction_Actions();

		/**
		 * The meta object literal for the '<em><b>Synchro Type</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute FUNCTION__SYNCHRO_TYPE = eINSTANCE.getFunction_SynchroType();

		/**
		 * The meta object literal for the '<em><b>Sched Policy</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute FUNCTION__SCHED_POLICY = eINSTANCE.getFunction_SchedPolicy();

		/**
		 * The meta object literal for the '<em><b>Other Policy</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute FUNCTION__OTHER_POLICY = eINSTANCE.getFunction_OtherPolicy();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.ActionImpl <em>Action</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.ActionImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getAction()
		 * @generated
		 */
		EClass ACTION = eINSTANCE.getAction();

		/**
		 * The meta object literal for the '<em><b>Function</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ACTION__FUNCTION = eINSTANCE.getAction_Function();

		/**
		 * The meta object literal for the '<em><b>Start Date</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute ACTION__START_DATE = eINSTANCE.getAction_StartDate();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.RTActionImpl <em>RT Action</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.RTActionImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getRTAction()
		 * @generated
		 */
		EClass RT_ACTION = eINSTANCE.getRTAction();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.PortImpl <em>Port</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.PortImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getPort()
		 * @generated
		 */
		EClass PORT = eINSTANCE.getPort();

		/**
		 * The meta object literal for the '<em><b>Module</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference PORT__MODULE = eINSTANCE.getPort_Module();

		/**
		 * The meta object literal for the '<em><b>Data Type</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute PORT__DATA_TYPE = eINSTANCE.getPort_DataType();

		/**
		 * The meta object literal for the '<em><b>Message Type</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute PORT__MESSAGE_TYPE = eINSTANCE.getPort_MessageType();

		/**
		 * The meta object literal for the '<em><b>Topic</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute PORT__TOPIC = eINSTANCE.getPort_Topic();

		/**
		 * The meta object literal for the '<em><b>Normalized Message Type</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation PORT___NORMALIZED_MESSAGE_TYPE = eINSTANCE.getPort__NormalizedMessageType();

		/**
		 * The meta object literal for the '<em><b>Topic Problem</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation PORT___TOPIC_PROBLEM = eINSTANCE.getPort__TopicProblem();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.EntryPortImpl <em>Entry Port</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.EntryPortImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getEntryPort()
		 * @generated
		 */
		EClass ENTRY_PORT = eINSTANCE.getEntryPort();

		/**
		 * The meta object literal for the '<em><b>Incoming</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ENTRY_PORT__INCOMING = eINSTANCE.getEntryPort_Incoming();

		/**
		 * The meta object literal for the '<em><b>Suppressed By</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ENTRY_PORT__SUPPRESSED_BY = eINSTANCE.getEntryPort_SuppressedBy();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.OutputPortImpl <em>Output Port</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.OutputPortImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getOutputPort()
		 * @generated
		 */
		EClass OUTPUT_PORT = eINSTANCE.getOutputPort();

		/**
		 * The meta object literal for the '<em><b>Outgoing</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference OUTPUT_PORT__OUTGOING = eINSTANCE.getOutputPort_Outgoing();

		/**
		 * The meta object literal for the '<em><b>Inhibited By</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference OUTPUT_PORT__INHIBITED_BY = eINSTANCE.getOutputPort_InhibitedBy();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.ConnectionImpl <em>Connection</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.ConnectionImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getConnection()
		 * @generated
		 */
		EClass CONNECTION = eINSTANCE.getConnection();

		/**
		 * The meta object literal for the '<em><b>Architecture</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference CONNECTION__ARCHITECTURE = eINSTANCE.getConnection_Architecture();

		/**
		 * The meta object literal for the '<em><b>Source</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference CONNECTION__SOURCE = eINSTANCE.getConnection_Source();

		/**
		 * The meta object literal for the '<em><b>Target</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference CONNECTION__TARGET = eINSTANCE.getConnection_Target();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.SubsumptionLinkImpl <em>Subsumption Link</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.SubsumptionLinkImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getSubsumptionLink()
		 * @generated
		 */
		EClass SUBSUMPTION_LINK = eINSTANCE.getSubsumptionLink();

		/**
		 * The meta object literal for the '<em><b>Trigger</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference SUBSUMPTION_LINK__TRIGGER = eINSTANCE.getSubsumptionLink_Trigger();

		/**
		 * The meta object literal for the '<em><b>Duration</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute SUBSUMPTION_LINK__DURATION = eINSTANCE.getSubsumptionLink_Duration();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.InhibitorImpl <em>Inhibitor</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.InhibitorImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getInhibitor()
		 * @generated
		 */
		EClass INHIBITOR = eINSTANCE.getInhibitor();

		/**
		 * The meta object literal for the '<em><b>Module</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference INHIBITOR__MODULE = eINSTANCE.getInhibitor_Module();

		/**
		 * The meta object literal for the '<em><b>Target</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference INHIBITOR__TARGET = eINSTANCE.getInhibitor_Target();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.SuppressorImpl <em>Suppressor</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.SuppressorImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getSuppressor()
		 * @generated
		 */
		EClass SUPPRESSOR = eINSTANCE.getSuppressor();

		/**
		 * The meta object literal for the '<em><b>Module</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference SUPPRESSOR__MODULE = eINSTANCE.getSuppressor_Module();

		/**
		 * The meta object literal for the '<em><b>Target</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference SUPPRESSOR__TARGET = eINSTANCE.getSuppressor_Target();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.DeviceImpl <em>Device</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.DeviceImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getDevice()
		 * @generated
		 */
		EClass DEVICE = eINSTANCE.getDevice();

		/**
		 * The meta object literal for the '<em><b>Kind</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute DEVICE__KIND = eINSTANCE.getDevice_Kind();

		/**
		 * The meta object literal for the '<em><b>Data Type</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute DEVICE__DATA_TYPE = eINSTANCE.getDevice_DataType();

		/**
		 * The meta object literal for the '<em><b>Period</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute DEVICE__PERIOD = eINSTANCE.getDevice_Period();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.SensorImpl <em>Sensor</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.SensorImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getSensor()
		 * @generated
		 */
		EClass SENSOR = eINSTANCE.getSensor();

		/**
		 * The meta object literal for the '<em><b>Architecture</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference SENSOR__ARCHITECTURE = eINSTANCE.getSensor_Architecture();

		/**
		 * The meta object literal for the '<em><b>Modules</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference SENSOR__MODULES = eINSTANCE.getSensor_Modules();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.ActuatorImpl <em>Actuator</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.ActuatorImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getActuator()
		 * @generated
		 */
		EClass ACTUATOR = eINSTANCE.getActuator();

		/**
		 * The meta object literal for the '<em><b>Architecture</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ACTUATOR__ARCHITECTURE = eINSTANCE.getActuator_Architecture();

		/**
		 * The meta object literal for the '<em><b>Modules</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ACTUATOR__MODULES = eINSTANCE.getActuator_Modules();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.MissionImpl <em>Mission</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.MissionImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getMission()
		 * @generated
		 */
		EClass MISSION = eINSTANCE.getMission();

		/**
		 * The meta object literal for the '<em><b>Architecture</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MISSION__ARCHITECTURE = eINSTANCE.getMission_Architecture();

		/**
		 * The meta object literal for the '<em><b>Goals</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MISSION__GOALS = eINSTANCE.getMission_Goals();

		/**
		 * The meta object literal for the '<em><b>Plans</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference MISSION__PLANS = eINSTANCE.getMission_Plans();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.GoalImpl <em>Goal</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.GoalImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getGoal()
		 * @generated
		 */
		EClass GOAL = eINSTANCE.getGoal();

		/**
		 * The meta object literal for the '<em><b>Mission</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference GOAL__MISSION = eINSTANCE.getGoal_Mission();

		/**
		 * The meta object literal for the '<em><b>Parent Goal</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference GOAL__PARENT_GOAL = eINSTANCE.getGoal_ParentGoal();

		/**
		 * The meta object literal for the '<em><b>Sub Goals</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference GOAL__SUB_GOALS = eINSTANCE.getGoal_SubGoals();

		/**
		 * The meta object literal for the '<em><b>Priority</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute GOAL__PRIORITY = eINSTANCE.getGoal_Priority();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.PlanImpl <em>Plan</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.PlanImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getPlan()
		 * @generated
		 */
		EClass PLAN = eINSTANCE.getPlan();

		/**
		 * The meta object literal for the '<em><b>Mission</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference PLAN__MISSION = eINSTANCE.getPlan_Mission();

		/**
		 * The meta object literal for the '<em><b>Activities</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference PLAN__ACTIVITIES = eINSTANCE.getPlan_Activities();

		/**
		 * The meta object literal for the '<em><b>Achieves</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference PLAN__ACHIEVES = eINSTANCE.getPlan_Achieves();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.ActivityImpl <em>Activity</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.ActivityImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getActivity()
		 * @generated
		 */
		EClass ACTIVITY = eINSTANCE.getActivity();

		/**
		 * The meta object literal for the '<em><b>Plan</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ACTIVITY__PLAN = eINSTANCE.getActivity_Plan();

		/**
		 * The meta object literal for the '<em><b>Actions</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ACTIVITY__ACTIONS = eINSTANCE.getActivity_Actions();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.SupervisorImpl <em>Supervisor</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.SupervisorImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getSupervisor()
		 * @generated
		 */
		EClass SUPERVISOR = eINSTANCE.getSupervisor();

		/**
		 * The meta object literal for the '<em><b>Architecture</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference SUPERVISOR__ARCHITECTURE = eINSTANCE.getSupervisor_Architecture();

		/**
		 * The meta object literal for the '<em><b>Plans</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference SUPERVISOR__PLANS = eINSTANCE.getSupervisor_Plans();

		/**
		 * The meta object literal for the '<em><b>Realised By</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference SUPERVISOR__REALISED_BY = eINSTANCE.getSupervisor_RealisedBy();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.OrderImpl <em>Order</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.OrderImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getOrder()
		 * @generated
		 */
		EClass ORDER = eINSTANCE.getOrder();

		/**
		 * The meta object literal for the '<em><b>Architecture</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ORDER__ARCHITECTURE = eINSTANCE.getOrder_Architecture();

		/**
		 * The meta object literal for the '<em><b>Issuer</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute ORDER__ISSUER = eINSTANCE.getOrder_Issuer();

		/**
		 * The meta object literal for the '<em><b>Receiver</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ORDER__RECEIVER = eINSTANCE.getOrder_Receiver();

		/**
		 * The meta object literal for the '<em><b>Requests</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference ORDER__REQUESTS = eINSTANCE.getOrder_Requests();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.DatabaseImpl <em>Database</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.DatabaseImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getDatabase()
		 * @generated
		 */
		EClass DATABASE = eINSTANCE.getDatabase();

		/**
		 * The meta object literal for the '<em><b>Architecture</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference DATABASE__ARCHITECTURE = eINSTANCE.getDatabase_Architecture();

		/**
		 * The meta object literal for the '<em><b>Knowledge</b></em>' containment reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference DATABASE__KNOWLEDGE = eINSTANCE.getDatabase_Knowledge();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.KnowledgeImpl <em>Knowledge</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.KnowledgeImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getKnowledge()
		 * @generated
		 */
		EClass KNOWLEDGE = eINSTANCE.getKnowledge();

		/**
		 * The meta object literal for the '<em><b>Database</b></em>' container reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference KNOWLEDGE__DATABASE = eINSTANCE.getKnowledge_Database();

		/**
		 * The meta object literal for the '<em><b>Data Type</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute KNOWLEDGE__DATA_TYPE = eINSTANCE.getKnowledge_DataType();

		/**
		 * The meta object literal for the '<em><b>Used By</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference KNOWLEDGE__USED_BY = eINSTANCE.getKnowledge_UsedBy();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.ProcessorImpl <em>Processor</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.ProcessorImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getProcessor()
		 * @generated
		 */
		EClass PROCESSOR = eINSTANCE.getProcessor();

		/**
		 * The meta object literal for the '<em><b>Sched Policy</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute PROCESSOR__SCHED_POLICY = eINSTANCE.getProcessor_SchedPolicy();

		/**
		 * The meta object literal for the '<em><b>Core</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute PROCESSOR__CORE = eINSTANCE.getProcessor_Core();

		/**
		 * The meta object literal for the '<em><b>Modules</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference PROCESSOR__MODULES = eINSTANCE.getProcessor_Modules();

		/**
		 * The meta object literal for the '<em><b>Host</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute PROCESSOR__HOST = eINSTANCE.getProcessor_Host();

		/**
		 * The meta object literal for the '<em><b>Link Latency</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute PROCESSOR__LINK_LATENCY = eINSTANCE.getProcessor_LinkLatency();

		/**
		 * The meta object literal for the '<em><b>Package Problem</b></em>' operation.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EOperation PROCESSOR___PACKAGE_PROBLEM = eINSTANCE.getProcessor__PackageProblem();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.impl.LatencyRequirementImpl <em>Latency Requirement</em>}' class.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.impl.LatencyRequirementImpl
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getLatencyRequirement()
		 * @generated
		 */
		EClass LATENCY_REQUIREMENT = eINSTANCE.getLatencyRequirement();

		/**
		 * The meta object literal for the '<em><b>Source</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference LATENCY_REQUIREMENT__SOURCE = eINSTANCE.getLatencyRequirement_Source();

		/**
		 * The meta object literal for the '<em><b>Target</b></em>' reference feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference LATENCY_REQUIREMENT__TARGET = eINSTANCE.getLatencyRequirement_Target();

		/**
		 * The meta object literal for the '<em><b>Max Latency</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute LATENCY_REQUIREMENT__MAX_LATENCY = eINSTANCE.getLatencyRequirement_MaxLatency();

		/**
		 * The meta object literal for the '<em><b>Kind</b></em>' attribute feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EAttribute LATENCY_REQUIREMENT__KIND = eINSTANCE.getLatencyRequirement_Kind();

		/**
		 * The meta object literal for the '<em><b>Via</b></em>' reference list feature.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @generated
		 */
		EReference LATENCY_REQUIREMENT__VIA = eINSTANCE.getLatencyRequirement_Via();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.ArchitectureCategory <em>Architecture Category</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.ArchitectureCategory
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getArchitectureCategory()
		 * @generated
		 */
		EEnum ARCHITECTURE_CATEGORY = eINSTANCE.getArchitectureCategory();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.ElementType <em>Element Type</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.ElementType
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getElementType()
		 * @generated
		 */
		EEnum ELEMENT_TYPE = eINSTANCE.getElementType();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.ExecutionType <em>Execution Type</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.ExecutionType
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getExecutionType()
		 * @generated
		 */
		EEnum EXECUTION_TYPE = eINSTANCE.getExecutionType();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.TimeUnit <em>Time Unit</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.TimeUnit
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getTimeUnit()
		 * @generated
		 */
		EEnum TIME_UNIT = eINSTANCE.getTimeUnit();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.SynchronisationType <em>Synchronisation Type</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.SynchronisationType
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getSynchronisationType()
		 * @generated
		 */
		EEnum SYNCHRONISATION_TYPE = eINSTANCE.getSynchronisationType();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.SchedulingPolicy <em>Scheduling Policy</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.SchedulingPolicy
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getSchedulingPolicy()
		 * @generated
		 */
		EEnum SCHEDULING_POLICY = eINSTANCE.getSchedulingPolicy();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.DataType <em>Data Type</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.DataType
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getDataType()
		 * @generated
		 */
		EEnum DATA_TYPE = eINSTANCE.getDataType();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.NodeLifecycle <em>Node Lifecycle</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.NodeLifecycle
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getNodeLifecycle()
		 * @generated
		 */
		EEnum NODE_LIFECYCLE = eINSTANCE.getNodeLifecycle();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.PackageLayout <em>Package Layout</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.PackageLayout
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getPackageLayout()
		 * @generated
		 */
		EEnum PACKAGE_LAYOUT = eINSTANCE.getPackageLayout();

		/**
		 * The meta object literal for the '{@link org.rsaml.model.LatencyKind <em>Latency Kind</em>}' enum.
		 * <!-- begin-user-doc -->
		 * <!-- end-user-doc -->
		 * @see org.rsaml.model.LatencyKind
		 * @see org.rsaml.model.impl.RsamlPackageImpl#getLatencyKind()
		 * @generated
		 */
		EEnum LATENCY_KIND = eINSTANCE.getLatencyKind();

	}

} //RsamlPackage
