/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.impl;

import java.util.Collection;

import org.eclipse.emf.common.notify.Notification;
import org.eclipse.emf.common.notify.NotificationChain;

import org.eclipse.emf.common.util.EList;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.InternalEObject;

import org.eclipse.emf.ecore.impl.ENotificationImpl;

import org.eclipse.emf.ecore.util.EObjectContainmentEList;
import org.eclipse.emf.ecore.util.EObjectContainmentWithInverseEList;
import org.eclipse.emf.ecore.util.InternalEList;

import org.rsaml.model.Actuator;
import org.rsaml.model.Architecture;
import org.rsaml.model.ArchitectureCategory;
import org.rsaml.model.Connection;
import org.rsaml.model.Database;
import org.rsaml.model.LatencyRequirement;
import org.rsaml.model.Layer;
import org.rsaml.model.Mission;
import org.rsaml.model.NodeLifecycle;
import org.rsaml.model.Order;
import org.rsaml.model.PackageLayout;
import org.rsaml.model.Processor;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.Sensor;
import org.rsaml.model.Supervisor;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Architecture</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getCategory <em>Category</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getDeclaredLayers <em>Declared Layers</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getLifecycle <em>Lifecycle</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getPackages <em>Packages</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getLayers <em>Layers</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getConnections <em>Connections</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getSensors <em>Sensors</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getActuators <em>Actuators</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getMissions <em>Missions</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getSupervisors <em>Supervisors</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getOrders <em>Orders</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getDatabases <em>Databases</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getProcessors <em>Processors</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ArchitectureImpl#getLatencyRequirements <em>Latency Requirements</em>}</li>
 * </ul>
 *
 * @generated
 */
public class ArchitectureImpl extends NamedElementImpl implements Architecture {
	/**
	 * The default value of the '{@link #getCategory() <em>Category</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getCategory()
	 * @generated
	 * @ordered
	 */
	protected static final ArchitectureCategory CATEGORY_EDEFAULT = ArchitectureCategory.HYBRID;

	/**
	 * The cached value of the '{@link #getCategory() <em>Category</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getCategory()
	 * @generated
	 * @ordered
	 */
	protected ArchitectureCategory category = CATEGORY_EDEFAULT;

	/**
	 * The default value of the '{@link #getDeclaredLayers() <em>Declared Layers</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getDeclaredLayers()
	 * @generated
	 * @ordered
	 */
	protected static final int DECLARED_LAYERS_EDEFAULT = 0;

	/**
	 * The cached value of the '{@link #getDeclaredLayers() <em>Declared Layers</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getDeclaredLayers()
	 * @generated
	 * @ordered
	 */
	protected int declaredLayers = DECLARED_LAYERS_EDEFAULT;

	/**
	 * The default value of the '{@link #getLifecycle() <em>Lifecycle</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getLifecycle()
	 * @generated
	 * @ordered
	 */
	protected static final NodeLifecycle LIFECYCLE_EDEFAULT = NodeLifecycle.PLAIN;

	/**
	 * The cached value of the '{@link #getLifecycle() <em>Lifecycle</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getLifecycle()
	 * @generated
	 * @ordered
	 */
	protected NodeLifecycle lifecycle = LIFECYCLE_EDEFAULT;

	/**
	 * The default value of the '{@link #getPackages() <em>Packages</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getPackages()
	 * @generated
	 * @ordered
	 */
	protected static final PackageLayout PACKAGES_EDEFAULT = PackageLayout.SINGLE;

	/**
	 * The cached value of the '{@link #getPackages() <em>Packages</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getPackages()
	 * @generated
	 * @ordered
	 */
	protected PackageLayout packages = PACKAGES_EDEFAULT;

	/**
	 * The cached value of the '{@link #getLayers() <em>Layers</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getLayers()
	 * @generated
	 * @ordered
	 */
	protected EList<Layer> layers;

	/**
	 * The cached value of the '{@link #getConnections() <em>Connections</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getConnections()
	 * @generated
	 * @ordered
	 */
	protected EList<Connection> connections;

	/**
	 * The cached value of the '{@link #getSensors() <em>Sensors</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSensors()
	 * @generated
	 * @ordered
	 */
	protected EList<Sensor> sensors;

	/**
	 * The cached value of the '{@link #getActuators() <em>Actuators</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getActuators()
	 * @generated
	 * @ordered
	 */
	protected EList<Actuator> actuators;

	/**
	 * The cached value of the '{@link #getMissions() <em>Missions</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getMissions()
	 * @generated
	 * @ordered
	 */
	protected EList<Mission> missions;

	/**
	 * The cached value of the '{@link #getSupervisors() <em>Supervisors</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSupervisors()
	 * @generated
	 * @ordered
	 */
	protected EList<Supervisor> supervisors;

	/**
	 * The cached value of the '{@link #getOrders() <em>Orders</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getOrders()
	 * @generated
	 * @ordered
	 */
	protected EList<Order> orders;

	/**
	 * The cached value of the '{@link #getDatabases() <em>Databases</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getDatabases()
	 * @generated
	 * @ordered
	 */
	protected EList<Database> databases;

	/**
	 * The cached value of the '{@link #getProcessors() <em>Processors</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getProcessors()
	 * @generated
	 * @ordered
	 */
	protected EList<Processor> processors;

	/**
	 * The cached value of the '{@link #getLatencyRequirements() <em>Latency Requirements</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getLatencyRequirements()
	 * @generated
	 * @ordered
	 */
	protected EList<LatencyRequirement> latencyRequirements;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected ArchitectureImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.ARCHITECTURE;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public ArchitectureCategory getCategory() {
		return category;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setCategory(ArchitectureCategory newCategory) {
		ArchitectureCategory oldCategory = category;
		category = newCategory == null ? CATEGORY_EDEFAULT : newCategory;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.ARCHITECTURE__CATEGORY, oldCategory, category));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public int getDeclaredLayers() {
		return declaredLayers;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setDeclaredLayers(int newDeclaredLayers) {
		int oldDeclaredLayers = declaredLayers;
		declaredLayers = newDeclaredLayers;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.ARCHITECTURE__DECLARED_LAYERS, oldDeclaredLayers, declaredLayers));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public NodeLifecycle getLifecycle() {
		return lifecycle;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setLifecycle(NodeLifecycle newLifecycle) {
		NodeLifecycle oldLifecycle = lifecycle;
		lifecycle = newLifecycle == null ? LIFECYCLE_EDEFAULT : newLifecycle;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.ARCHITECTURE__LIFECYCLE, oldLifecycle, lifecycle));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public PackageLayout getPackages() {
		return packages;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setPackages(PackageLayout newPackages) {
		PackageLayout oldPackages = packages;
		packages = newPackages == null ? PACKAGES_EDEFAULT : newPackages;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.ARCHITECTURE__PACKAGES, oldPackages, packages));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Layer> getLayers() {
		if (layers == null) {
			layers = new EObjectContainmentWithInverseEList<Layer>(Layer.class, this, RsamlPackage.ARCHITECTURE__LAYERS, RsamlPackage.LAYER__ARCHITECTURE);
		}
		return layers;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Connection> getConnections() {
		if (connections == null) {
			connections = new EObjectContainmentWithInverseEList<Connection>(Connection.class, this, RsamlPackage.ARCHITECTURE__CONNECTIONS, RsamlPackage.CONNECTION__ARCHITECTURE);
		}
		return connections;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Sensor> getSensors() {
		if (sensors == null) {
			sensors = new EObjectContainmentWithInverseEList<Sensor>(Sensor.class, this, RsamlPackage.ARCHITECTURE__SENSORS, RsamlPackage.SENSOR__ARCHITECTURE);
		}
		return sensors;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Actuator> getActuators() {
		if (actuators == null) {
			actuators = new EObjectContainmentWithInverseEList<Actuator>(Actuator.class, this, RsamlPackage.ARCHITECTURE__ACTUATORS, RsamlPackage.ACTUATOR__ARCHITECTURE);
		}
		return actuators;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Mission> getMissions() {
		if (missions == null) {
			missions = new EObjectContainmentWithInverseEList<Mission>(Mission.class, this, RsamlPackage.ARCHITECTURE__MISSIONS, RsamlPackage.MISSION__ARCHITECTURE);
		}
		return missions;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Supervisor> getSupervisors() {
		if (supervisors == null) {
			supervisors = new EObjectContainmentWithInverseEList<Supervisor>(Supervisor.class, this, RsamlPackage.ARCHITECTURE__SUPERVISORS, RsamlPackage.SUPERVISOR__ARCHITECTURE);
		}
		return supervisors;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Order> getOrders() {
		if (orders == null) {
			orders = new EObjectContainmentWithInverseEList<Order>(Order.class, this, RsamlPackage.ARCHITECTURE__ORDERS, RsamlPackage.ORDER__ARCHITECTURE);
		}
		return orders;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Database> getDatabases() {
		if (databases == null) {
			databases = new EObjectContainmentWithInverseEList<Database>(Database.class, this, RsamlPackage.ARCHITECTURE__DATABASES, RsamlPackage.DATABASE__ARCHITECTURE);
		}
		return databases;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Processor> getProcessors() {
		if (processors == null) {
			processors = new EObjectContainmentEList<Processor>(Processor.class, this, RsamlPackage.ARCHITECTURE__PROCESSORS);
		}
		return processors;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<LatencyRequirement> getLatencyRequirements() {
		if (latencyRequirements == null) {
			latencyRequirements = new EObjectContainmentEList<LatencyRequirement>(LatencyRequirement.class, this, RsamlPackage.ARCHITECTURE__LATENCY_REQUIREMENTS);
		}
		return latencyRequirements;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@SuppressWarnings("unchecked")
	@Override
	public NotificationChain eInverseAdd(InternalEObject otherEnd, int featureID, NotificationChain msgs) {
		switch (featureID) {
			case RsamlPackage.ARCHITECTURE__LAYERS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getLayers()).basicAdd(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__CONNECTIONS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getConnections()).basicAdd(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__SENSORS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getSensors()).basicAdd(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__ACTUATORS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getActuators()).basicAdd(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__MISSIONS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getMissions()).basicAdd(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__SUPERVISORS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getSupervisors()).basicAdd(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__ORDERS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getOrders()).basicAdd(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__DATABASES:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getDatabases()).basicAdd(otherEnd, msgs);
		}
		return super.eInverseAdd(otherEnd, featureID, msgs);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public NotificationChain eInverseRemove(InternalEObject otherEnd, int featureID, NotificationChain msgs) {
		switch (featureID) {
			case RsamlPackage.ARCHITECTURE__LAYERS:
				return ((InternalEList<?>)getLayers()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__CONNECTIONS:
				return ((InternalEList<?>)getConnections()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__SENSORS:
				return ((InternalEList<?>)getSensors()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__ACTUATORS:
				return ((InternalEList<?>)getActuators()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__MISSIONS:
				return ((InternalEList<?>)getMissions()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__SUPERVISORS:
				return ((InternalEList<?>)getSupervisors()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__ORDERS:
				return ((InternalEList<?>)getOrders()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__DATABASES:
				return ((InternalEList<?>)getDatabases()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__PROCESSORS:
				return ((InternalEList<?>)getProcessors()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ARCHITECTURE__LATENCY_REQUIREMENTS:
				return ((InternalEList<?>)getLatencyRequirements()).basicRemove(otherEnd, msgs);
		}
		return super.eInverseRemove(otherEnd, featureID, msgs);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Object eGet(int featureID, boolean resolve, boolean coreType) {
		switch (featureID) {
			case RsamlPackage.ARCHITECTURE__CATEGORY:
				return getCategory();
			case RsamlPackage.ARCHITECTURE__DECLARED_LAYERS:
				return getDeclaredLayers();
			case RsamlPackage.ARCHITECTURE__LIFECYCLE:
				return getLifecycle();
			case RsamlPackage.ARCHITECTURE__PACKAGES:
				return getPackages();
			case RsamlPackage.ARCHITECTURE__LAYERS:
				return getLayers();
			case RsamlPackage.ARCHITECTURE__CONNECTIONS:
				return getConnections();
			case RsamlPackage.ARCHITECTURE__SENSORS:
				return getSensors();
			case RsamlPackage.ARCHITECTURE__ACTUATORS:
				return getActuators();
			case RsamlPackage.ARCHITECTURE__MISSIONS:
				return getMissions();
			case RsamlPackage.ARCHITECTURE__SUPERVISORS:
				return getSupervisors();
			case RsamlPackage.ARCHITECTURE__ORDERS:
				return getOrders();
			case RsamlPackage.ARCHITECTURE__DATABASES:
				return getDatabases();
			case RsamlPackage.ARCHITECTURE__PROCESSORS:
				return getProcessors();
			case RsamlPackage.ARCHITECTURE__LATENCY_REQUIREMENTS:
				return getLatencyRequirements();
		}
		return super.eGet(featureID, resolve, coreType);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@SuppressWarnings("unchecked")
	@Override
	public void eSet(int featureID, Object newValue) {
		switch (featureID) {
			case RsamlPackage.ARCHITECTURE__CATEGORY:
				setCategory((ArchitectureCategory)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__DECLARED_LAYERS:
				setDeclaredLayers((Integer)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__LIFECYCLE:
				setLifecycle((NodeLifecycle)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__PACKAGES:
				setPackages((PackageLayout)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__LAYERS:
				getLayers().clear();
				getLayers().addAll((Collection<? extends Layer>)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__CONNECTIONS:
				getConnections().clear();
				getConnections().addAll((Collection<? extends Connection>)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__SENSORS:
				getSensors().clear();
				getSensors().addAll((Collection<? extends Sensor>)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__ACTUATORS:
				getActuators().clear();
				getActuators().addAll((Collection<? extends Actuator>)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__MISSIONS:
				getMissions().clear();
				getMissions().addAll((Collection<? extends Mission>)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__SUPERVISORS:
				getSupervisors().clear();
				getSupervisors().addAll((Collection<? extends Supervisor>)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__ORDERS:
				getOrders().clear();
				getOrders().addAll((Collection<? extends Order>)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__DATABASES:
				getDatabases().clear();
				getDatabases().addAll((Collection<? extends Database>)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__PROCESSORS:
				getProcessors().clear();
				getProcessors().addAll((Collection<? extends Processor>)newValue);
				return;
			case RsamlPackage.ARCHITECTURE__LATENCY_REQUIREMENTS:
				getLatencyRequirements().clear();
				getLatencyRequirements().addAll((Collection<? extends LatencyRequirement>)newValue);
				return;
		}
		super.eSet(featureID, newValue);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void eUnset(int featureID) {
		switch (featureID) {
			case RsamlPackage.ARCHITECTURE__CATEGORY:
				setCategory(CATEGORY_EDEFAULT);
				return;
			case RsamlPackage.ARCHITECTURE__DECLARED_LAYERS:
				setDeclaredLayers(DECLARED_LAYERS_EDEFAULT);
				return;
			case RsamlPackage.ARCHITECTURE__LIFECYCLE:
				setLifecycle(LIFECYCLE_EDEFAULT);
				return;
			case RsamlPackage.ARCHITECTURE__PACKAGES:
				setPackages(PACKAGES_EDEFAULT);
				return;
			case RsamlPackage.ARCHITECTURE__LAYERS:
				getLayers().clear();
				return;
			case RsamlPackage.ARCHITECTURE__CONNECTIONS:
				getConnections().clear();
				return;
			case RsamlPackage.ARCHITECTURE__SENSORS:
				getSensors().clear();
				return;
			case RsamlPackage.ARCHITECTURE__ACTUATORS:
				getActuators().clear();
				return;
			case RsamlPackage.ARCHITECTURE__MISSIONS:
				getMissions().clear();
				return;
			case RsamlPackage.ARCHITECTURE__SUPERVISORS:
				getSupervisors().clear();
				return;
			case RsamlPackage.ARCHITECTURE__ORDERS:
				getOrders().clear();
				return;
			case RsamlPackage.ARCHITECTURE__DATABASES:
				getDatabases().clear();
				return;
			case RsamlPackage.ARCHITECTURE__PROCESSORS:
				getProcessors().clear();
				return;
			case RsamlPackage.ARCHITECTURE__LATENCY_REQUIREMENTS:
				getLatencyRequirements().clear();
				return;
		}
		super.eUnset(featureID);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public boolean eIsSet(int featureID) {
		switch (featureID) {
			case RsamlPackage.ARCHITECTURE__CATEGORY:
				return category != CATEGORY_EDEFAULT;
			case RsamlPackage.ARCHITECTURE__DECLARED_LAYERS:
				return declaredLayers != DECLARED_LAYERS_EDEFAULT;
			case RsamlPackage.ARCHITECTURE__LIFECYCLE:
				return lifecycle != LIFECYCLE_EDEFAULT;
			case RsamlPackage.ARCHITECTURE__PACKAGES:
				return packages != PACKAGES_EDEFAULT;
			case RsamlPackage.ARCHITECTURE__LAYERS:
				return layers != null && !layers.isEmpty();
			case RsamlPackage.ARCHITECTURE__CONNECTIONS:
				return connections != null && !connections.isEmpty();
			case RsamlPackage.ARCHITECTURE__SENSORS:
				return sensors != null && !sensors.isEmpty();
			case RsamlPackage.ARCHITECTURE__ACTUATORS:
				return actuators != null && !actuators.isEmpty();
			case RsamlPackage.ARCHITECTURE__MISSIONS:
				return missions != null && !missions.isEmpty();
			case RsamlPackage.ARCHITECTURE__SUPERVISORS:
				return supervisors != null && !supervisors.isEmpty();
			case RsamlPackage.ARCHITECTURE__ORDERS:
				return orders != null && !orders.isEmpty();
			case RsamlPackage.ARCHITECTURE__DATABASES:
				return databases != null && !databases.isEmpty();
			case RsamlPackage.ARCHITECTURE__PROCESSORS:
				return processors != null && !processors.isEmpty();
			case RsamlPackage.ARCHITECTURE__LATENCY_REQUIREMENTS:
				return latencyRequirements != null && !latencyRequirements.isEmpty();
		}
		return super.eIsSet(featureID);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public String toString() {
		if (eIsProxy()) return super.toString();

		StringBuilder result = new StringBuilder(super.toString());
		result.append(" (category: ");
		result.append(category);
		result.append(", declaredLayers: ");
		result.append(declaredLayers);
		result.append(", lifecycle: ");
		result.append(lifecycle);
		result.append(", packages: ");
		result.append(packages);
		result.append(')');
		return result.toString();
	}

} //ArchitectureImpl
