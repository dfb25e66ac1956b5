/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.impl;

import java.lang.reflect.InvocationTargetException;

import java.util.Collection;

import org.eclipse.emf.common.notify.Notification;
import org.eclipse.emf.common.notify.NotificationChain;

import org.eclipse.emf.common.util.EList;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.InternalEObject;

import org.eclipse.emf.ecore.impl.ENotificationImpl;

import org.eclipse.emf.ecore.util.EObjectContainmentWithInverseEList;
import org.eclipse.emf.ecore.util.EObjectWithInverseResolvingEList;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.util.InternalEList;

import org.rsaml.model.Actuator;
import org.rsaml.model.Function;
import org.rsaml.model.Inhibitor;
import org.rsaml.model.Layer;
import org.rsaml.model.NodeLifecycle;
import org.rsaml.model.Port;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.Sensor;
import org.rsaml.model.Suppressor;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Module</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.ModuleImpl#getLayer <em>Layer</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ModuleImpl#getFunctions <em>Functions</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ModuleImpl#getPorts <em>Ports</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ModuleImpl#getInhibitors <em>Inhibitors</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ModuleImpl#getSuppressors <em>Suppressors</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ModuleImpl#getSensors <em>Sensors</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ModuleImpl#getActuators <em>Actuators</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ModuleImpl#getLifecycle <em>Lifecycle</em>}</li>
 * </ul>
 *
 * @generated
 */
public class ModuleImpl extends RealTimeElementImpl implements org.rsaml.model.Module {
	/**
	 * The cached value of the '{@link #getFunctions() <em>Functions</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getFunctions()
	 * @generated
	 * @ordered
	 */
	protected EList<Function> functions;

	/**
	 * The cached value of the '{@link #getPorts() <em>Ports</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getPorts()
	 * @generated
	 * @ordered
	 */
	protected EList<Port> ports;

	/**
	 * The cached value of the '{@link #getInhibitors() <em>Inhibitors</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getInhibitors()
	 * @generated
	 * @ordered
	 */
	protected EList<Inhibitor> inhibitors;

	/**
	 * The cached value of the '{@link #getSuppressors() <em>Suppressors</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSuppressors()
	 * @generated
	 * @ordered
	 */
	protected EList<Suppressor> suppressors;

	/**
	 * The cached value of the '{@link #getSensors() <em>Sensors</em>}' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSensors()
	 * @generated
	 * @ordered
	 */
	protected EList<Sensor> sensors;

	/**
	 * The cached value of the '{@link #getActuators() <em>Actuators</em>}' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getActuators()
	 * @generated
	 * @ordered
	 */
	protected EList<Actuator> actuators;

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
	 * This is true if the Lifecycle attribute has been set.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	protected boolean lifecycleESet;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected ModuleImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.MODULE;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Layer getLayer() {
		if (eContainerFeatureID() != RsamlPackage.MODULE__LAYER) return null;
		return (Layer)eInternalContainer();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public NotificationChain basicSetLayer(Layer newLayer, NotificationChain msgs) {
		msgs = eBasicSetContainer((InternalEObject)newLayer, RsamlPackage.MODULE__LAYER, msgs);
		return msgs;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setLayer(Layer newLayer) {
		if (newLayer != eInternalContainer() || (eContainerFeatureID() != RsamlPackage.MODULE__LAYER && newLayer != null)) {
			if (EcoreUtil.isAncestor(this, newLayer))
				throw new IllegalArgumentException("Recursive containment not allowed for " + toString());
			NotificationChain msgs = null;
			if (eInternalContainer() != null)
				msgs = eBasicRemoveFromContainer(msgs);
			if (newLayer != null)
				msgs = ((InternalEObject)newLayer).eInverseAdd(this, RsamlPackage.LAYER__MODULES, Layer.class, msgs);
			msgs = basicSetLayer(newLayer, msgs);
			if (msgs != null) msgs.dispatch();
		}
		else if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.MODULE__LAYER, newLayer, newLayer));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Function> getFunctions() {
		if (functions == null) {
			functions = new EObjectContainmentWithInverseEList<Function>(Function.class, this, RsamlPackage.MODULE__FUNCTIONS, RsamlPackage.FUNCTION__MODULE);
		}
		return functions;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Port> getPorts() {
		if (ports == null) {
			ports = new EObjectContainmentWithInverseEList<Port>(Port.class, this, RsamlPackage.MODULE__PORTS, RsamlPackage.PORT__MODULE);
		}
		return ports;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Inhibitor> getInhibitors() {
		if (inhibitors == null) {
			inhibitors = new EObjectContainmentWithInverseEList<Inhibitor>(Inhibitor.class, this, RsamlPackage.MODULE__INHIBITORS, RsamlPackage.INHIBITOR__MODULE);
		}
		return inhibitors;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Suppressor> getSuppressors() {
		if (suppressors == null) {
			suppressors = new EObjectContainmentWithInverseEList<Suppressor>(Suppressor.class, this, RsamlPackage.MODULE__SUPPRESSORS, RsamlPackage.SUPPRESSOR__MODULE);
		}
		return suppressors;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Sensor> getSensors() {
		if (sensors == null) {
			sensors = new EObjectWithInverseResolvingEList.ManyInverse<Sensor>(Sensor.class, this, RsamlPackage.MODULE__SENSORS, RsamlPackage.SENSOR__MODULES);
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
			actuators = new EObjectWithInverseResolvingEList.ManyInverse<Actuator>(Actuator.class, this, RsamlPackage.MODULE__ACTUATORS, RsamlPackage.ACTUATOR__MODULES);
		}
		return actuators;
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
		boolean oldLifecycleESet = lifecycleESet;
		lifecycleESet = true;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.MODULE__LIFECYCLE, oldLifecycle, lifecycle, !oldLifecycleESet));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void unsetLifecycle() {
		NodeLifecycle oldLifecycle = lifecycle;
		boolean oldLifecycleESet = lifecycleESet;
		lifecycle = LIFECYCLE_EDEFAULT;
		lifecycleESet = false;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.UNSET, RsamlPackage.MODULE__LIFECYCLE, oldLifecycle, LIFECYCLE_EDEFAULT, oldLifecycleESet));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public boolean isSetLifecycle() {
		return lifecycleESet;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public NodeLifecycle effectiveLifecycle() {
		return isSetLifecycle() ? getLifecycle() : getLayer() != null && getLayer().getArchitecture() != null ? getLayer().getArchitecture().getLifecycle() : NodeLifecycle.PLAIN;
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
			case RsamlPackage.MODULE__LAYER:
				if (eInternalContainer() != null)
					msgs = eBasicRemoveFromContainer(msgs);
				return basicSetLayer((Layer)otherEnd, msgs);
			case RsamlPackage.MODULE__FUNCTIONS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getFunctions()).basicAdd(otherEnd, msgs);
			case RsamlPackage.MODULE__PORTS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getPorts()).basicAdd(otherEnd, msgs);
			case RsamlPackage.MODULE__INHIBITORS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getInhibitors()).basicAdd(otherEnd, msgs);
			case RsamlPackage.MODULE__SUPPRESSORS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getSuppressors()).basicAdd(otherEnd, msgs);
			case RsamlPackage.MODULE__SENSORS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getSensors()).basicAdd(otherEnd, msgs);
			case RsamlPackage.MODULE__ACTUATORS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getActuators()).basicAdd(otherEnd, msgs);
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
			case RsamlPackage.MODULE__LAYER:
				return basicSetLayer(null, msgs);
			case RsamlPackage.MODULE__FUNCTIONS:
				return ((InternalEList<?>)getFunctions()).basicRemove(otherEnd, msgs);
			case RsamlPackage.MODULE__PORTS:
				return ((InternalEList<?>)getPorts()).basicRemove(otherEnd, msgs);
			case RsamlPackage.MODULE__INHIBITORS:
				return ((InternalEList<?>)getInhibitors()).basicRemove(otherEnd, msgs);
			case RsamlPackage.MODULE__SUPPRESSORS:
				return ((InternalEList<?>)getSuppressors()).basicRemove(otherEnd, msgs);
			case RsamlPackage.MODULE__SENSORS:
				return ((InternalEList<?>)getSensors()).basicRemove(otherEnd, msgs);
			case RsamlPackage.MODULE__ACTUATORS:
				return ((InternalEList<?>)getActuators()).basicRemove(otherEnd, msgs);
		}
		return super.eInverseRemove(otherEnd, featureID, msgs);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public NotificationChain eBasicRemoveFromContainerFeature(NotificationChain msgs) {
		switch (eContainerFeatureID()) {
			case RsamlPackage.MODULE__LAYER:
				return eInternalContainer().eInverseRemove(this, RsamlPackage.LAYER__MODULES, Layer.class, msgs);
		}
		return super.eBasicRemoveFromContainerFeature(msgs);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Object eGet(int featureID, boolean resolve, boolean coreType) {
		switch (featureID) {
			case RsamlPackage.MODULE__LAYER:
				return getLayer();
			case RsamlPackage.MODULE__FUNCTIONS:
				return getFunctions();
			case RsamlPackage.MODULE__PORTS:
				return getPorts();
			case RsamlPackage.MODULE__INHIBITORS:
				return getInhibitors();
			case RsamlPackage.MODULE__SUPPRESSORS:
				return getSuppressors();
			case RsamlPackage.MODULE__SENSORS:
				return getSensors();
			case RsamlPackage.MODULE__ACTUATORS:
				return getActuators();
			case RsamlPackage.MODULE__LIFECYCLE:
				return getLifecycle();
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
			case RsamlPackage.MODULE__LAYER:
				setLayer((Layer)newValue);
				return;
			case RsamlPackage.MODULE__FUNCTIONS:
				getFunctions().clear();
				getFunctions().addAll((Collection<? extends Function>)newValue);
				return;
			case RsamlPackage.MODULE__PORTS:
				getPorts().clear();
				getPorts().addAll((Collection<? extends Port>)newValue);
				return;
			case RsamlPackage.MODULE__INHIBITORS:
				getInhibitors().clear();
				getInhibitors().addAll((Collection<? extends Inhibitor>)newValue);
				return;
			case RsamlPackage.MODULE__SUPPRESSORS:
				getSuppressors().clear();
				getSuppressors().addAll((Collection<? extends Suppressor>)newValue);
				return;
			case RsamlPackage.MODULE__SENSORS:
				getSensors().clear();
				getSensors().addAll((Collection<? extends Sensor>)newValue);
				return;
			case RsamlPackage.MODULE__ACTUATORS:
				getActuators().clear();
				getActuators().addAll((Collection<? extends Actuator>)newValue);
				return;
			case RsamlPackage.MODULE__LIFECYCLE:
				setLifecycle((NodeLifecycle)newValue);
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
			case RsamlPackage.MODULE__LAYER:
				setLayer((Layer)null);
				return;
			case RsamlPackage.MODULE__FUNCTIONS:
				getFunctions().clear();
				return;
			case RsamlPackage.MODULE__PORTS:
				getPorts().clear();
				return;
			case RsamlPackage.MODULE__INHIBITORS:
				getInhibitors().clear();
				return;
			case RsamlPackage.MODULE__SUPPRESSORS:
				getSuppressors().clear();
				return;
			case RsamlPackage.MODULE__SENSORS:
				getSensors().clear();
				return;
			case RsamlPackage.MODULE__ACTUATORS:
				getActuators().clear();
				return;
			case RsamlPackage.MODULE__LIFECYCLE:
				unsetLifecycle();
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
			case RsamlPackage.MODULE__LAYER:
				return getLayer() != null;
			case RsamlPackage.MODULE__FUNCTIONS:
				return functions != null && !functions.isEmpty();
			case RsamlPackage.MODULE__PORTS:
				return ports != null && !ports.isEmpty();
			case RsamlPackage.MODULE__INHIBITORS:
				return inhibitors != null && !inhibitors.isEmpty();
			case RsamlPackage.MODULE__SUPPRESSORS:
				return suppressors != null && !suppressors.isEmpty();
			case RsamlPackage.MODULE__SENSORS:
				return sensors != null && !sensors.isEmpty();
			case RsamlPackage.MODULE__ACTUATORS:
				return actuators != null && !actuators.isEmpty();
			case RsamlPackage.MODULE__LIFECYCLE:
				return isSetLifecycle();
		}
		return super.eIsSet(featureID);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Object eInvoke(int operationID, EList<?> arguments) throws InvocationTargetException {
		switch (operationID) {
			case RsamlPackage.MODULE___EFFECTIVE_LIFECYCLE:
				return effectiveLifecycle();
		}
		return super.eInvoke(operationID, arguments);
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
		result.append(" (lifecycle: ");
		if (lifecycleESet) result.append(lifecycle); else result.append("<unset>");
		result.append(')');
		return result.toString();
	}

} //ModuleImpl
