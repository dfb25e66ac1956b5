/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Architecture</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * The root of an RsaML model: a robot's software architecture, its layers and the connections between them, the robot's sensors and actuators, and its missions.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Architecture#getCategory <em>Category</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getDeclaredLayers <em>Declared Layers</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getLifecycle <em>Lifecycle</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getPackages <em>Packages</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getLayers <em>Layers</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getConnections <em>Connections</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getSensors <em>Sensors</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getActuators <em>Actuators</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getMissions <em>Missions</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getSupervisors <em>Supervisors</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getOrders <em>Orders</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getDatabases <em>Databases</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getProcessors <em>Processors</em>}</li>
 *   <li>{@link org.rsaml.model.Architecture#getLatencyRequirements <em>Latency Requirements</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getArchitecture()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA01_declaredLayerCount RSA09_uniqueNames RSA14_layerLevels'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA01_declaredLayerCount='declaredLayers = layers-&gt;size()' RSA09_uniqueNames='layers-&gt;isUnique(normalizedName()) and sensors-&gt;isUnique(normalizedName()) and actuators-&gt;isUnique(normalizedName()) and missions-&gt;isUnique(normalizedName()) and supervisors-&gt;isUnique(normalizedName()) and orders-&gt;isUnique(normalizedName()) and databases-&gt;isUnique(normalizedName())' RSA14_layerLevels='layers-&gt;isUnique(level) and layers-&gt;forAll(l | l.level &gt;= 0 and l.level &lt; layers-&gt;size())'"
 * @generated
 */
public interface Architecture extends NamedElement {
	/**
	 * Returns the value of the '<em><b>Category</b></em>' attribute.
	 * The default value is <code>"hybrid"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.ArchitectureCategory}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The category the architecture belongs to: centralized, hierarchical, behavioral (reactive), hybrid, or other.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Category</em>' attribute.
	 * @see org.rsaml.model.ArchitectureCategory
	 * @see #setCategory(ArchitectureCategory)
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Category()
	 * @model default="hybrid"
	 * @generated
	 */
	ArchitectureCategory getCategory();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Architecture#getCategory <em>Category</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Category</em>' attribute.
	 * @see org.rsaml.model.ArchitectureCategory
	 * @see #getCategory()
	 * @generated
	 */
	void setCategory(ArchitectureCategory value);

	/**
	 * Returns the value of the '<em><b>Declared Layers</b></em>' attribute.
	 * The default value is <code>"0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The number of layers the architect declares. It must equal the number of layers actually present in the architecture.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Declared Layers</em>' attribute.
	 * @see #setDeclaredLayers(int)
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_DeclaredLayers()
	 * @model default="0"
	 * @generated
	 */
	int getDeclaredLayers();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Architecture#getDeclaredLayers <em>Declared Layers</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Declared Layers</em>' attribute.
	 * @see #getDeclaredLayers()
	 * @generated
	 */
	void setDeclaredLayers(int value);

	/**
	 * Returns the value of the '<em><b>Lifecycle</b></em>' attribute.
	 * The default value is <code>"plain"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.NodeLifecycle}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Whether the modules become plain ROS 2 nodes (the default) or managed ones (rclcpp_lifecycle nodes that the launch files configure and activate); a module may choose otherwise with its own lifecycle. The C++ target has no node lifecycle and ignores it.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Lifecycle</em>' attribute.
	 * @see org.rsaml.model.NodeLifecycle
	 * @see #setLifecycle(NodeLifecycle)
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Lifecycle()
	 * @model default="plain"
	 * @generated
	 */
	NodeLifecycle getLifecycle();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Architecture#getLifecycle <em>Lifecycle</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Lifecycle</em>' attribute.
	 * @see org.rsaml.model.NodeLifecycle
	 * @see #getLifecycle()
	 * @generated
	 */
	void setLifecycle(NodeLifecycle value);

	/**
	 * Returns the value of the '<em><b>Packages</b></em>' attribute.
	 * The default value is <code>"single"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.PackageLayout}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * How the ROS 2 target divides the nodes into packages: one package for every node (single, the default), a package per layer (perLayer) or per processor (perProcessor); the message types the model names are in an interfaces package of their own in every layout. The C++ target ignores it.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Packages</em>' attribute.
	 * @see org.rsaml.model.PackageLayout
	 * @see #setPackages(PackageLayout)
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Packages()
	 * @model default="single"
	 * @generated
	 */
	PackageLayout getPackages();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Architecture#getPackages <em>Packages</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Packages</em>' attribute.
	 * @see org.rsaml.model.PackageLayout
	 * @see #getPackages()
	 * @generated
	 */
	void setPackages(PackageLayout value);

	/**
	 * Returns the value of the '<em><b>Layers</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Layer}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Layer#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The layers of the architecture, each with a level; level 0 is the lowest (closest to the hardware).
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Layers</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Layers()
	 * @see org.rsaml.model.Layer#getArchitecture
	 * @model opposite="architecture" containment="true" keys="name"
	 * @generated
	 */
	EList<Layer> getLayers();

	/**
	 * Returns the value of the '<em><b>Connections</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Connection}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Connection#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The data flows between module ports, each from an output port to an entry port.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Connections</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Connections()
	 * @see org.rsaml.model.Connection#getArchitecture
	 * @model opposite="architecture" containment="true"
	 * @generated
	 */
	EList<Connection> getConnections();

	/**
	 * Returns the value of the '<em><b>Sensors</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Sensor}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Sensor#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The robot's sensors, read by modules.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Sensors</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Sensors()
	 * @see org.rsaml.model.Sensor#getArchitecture
	 * @model opposite="architecture" containment="true" keys="name"
	 * @generated
	 */
	EList<Sensor> getSensors();

	/**
	 * Returns the value of the '<em><b>Actuators</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Actuator}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Actuator#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The robot's actuators, driven by modules.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Actuators</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Actuators()
	 * @see org.rsaml.model.Actuator#getArchitecture
	 * @model opposite="architecture" containment="true" keys="name"
	 * @generated
	 */
	EList<Actuator> getActuators();

	/**
	 * Returns the value of the '<em><b>Missions</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Mission}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Mission#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The missions the robot can be given.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Missions</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Missions()
	 * @see org.rsaml.model.Mission#getArchitecture
	 * @model opposite="architecture" containment="true" keys="name"
	 * @generated
	 */
	EList<Mission> getMissions();

	/**
	 * Returns the value of the '<em><b>Supervisors</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Supervisor}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Supervisor#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The supervisors that control the execution of plans.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Supervisors</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Supervisors()
	 * @see org.rsaml.model.Supervisor#getArchitecture
	 * @model opposite="architecture" containment="true" keys="name"
	 * @generated
	 */
	EList<Supervisor> getSupervisors();

	/**
	 * Returns the value of the '<em><b>Orders</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Order}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Order#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The orders that can be sent to the robot to perform a task.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Orders</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Orders()
	 * @see org.rsaml.model.Order#getArchitecture
	 * @model opposite="architecture" containment="true" keys="name"
	 * @generated
	 */
	EList<Order> getOrders();

	/**
	 * Returns the value of the '<em><b>Databases</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Database}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Database#getArchitecture <em>Architecture</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The databases and knowledge bases of the robot.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Databases</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Databases()
	 * @see org.rsaml.model.Database#getArchitecture
	 * @model opposite="architecture" containment="true" keys="name"
	 * @generated
	 */
	EList<Database> getDatabases();

	/**
	 * Returns the value of the '<em><b>Processors</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Processor}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Where the modules run (optional): each processor is one scheduling domain, e.g. one CPU core. Without processors every module runs on one processor.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Processors</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_Processors()
	 * @model containment="true" keys="name"
	 * @generated
	 */
	EList<Processor> getProcessors();

	/**
	 * Returns the value of the '<em><b>Latency Requirements</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.LatencyRequirement}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * End-to-end timing the architecture must meet (optional): from a sensor or an output port to an actuator or an entry port, at most a given latency.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Latency Requirements</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getArchitecture_LatencyRequirements()
	 * @model containment="true" keys="name"
	 * @generated
	 */
	EList<LatencyRequirement> getLatencyRequirements();

} // Architecture
