/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.impl;

import java.lang.reflect.InvocationTargetException;

import java.util.Collection;

import org.eclipse.emf.common.notify.Notification;

import org.eclipse.emf.common.util.EList;

import org.eclipse.emf.ecore.EClass;

import org.eclipse.emf.ecore.impl.ENotificationImpl;

import org.eclipse.emf.ecore.util.EObjectResolvingEList;

import org.rsaml.model.Processor;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Processor</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.ProcessorImpl#getTimeUnit <em>Time Unit</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ProcessorImpl#getSchedPolicy <em>Sched Policy</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ProcessorImpl#getCore <em>Core</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ProcessorImpl#getModules <em>Modules</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ProcessorImpl#getHost <em>Host</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ProcessorImpl#getLinkLatency <em>Link Latency</em>}</li>
 * </ul>
 *
 * @generated
 */
public class ProcessorImpl extends NamedElementImpl implements Processor {
	/**
	 * The default value of the '{@link #getTimeUnit() <em>Time Unit</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getTimeUnit()
	 * @generated
	 * @ordered
	 */
	protected static final TimeUnit TIME_UNIT_EDEFAULT = TimeUnit.MS;

	/**
	 * The cached value of the '{@link #getTimeUnit() <em>Time Unit</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getTimeUnit()
	 * @generated
	 * @ordered
	 */
	protected TimeUnit timeUnit = TIME_UNIT_EDEFAULT;

	/**
	 * The default value of the '{@link #getSchedPolicy() <em>Sched Policy</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSchedPolicy()
	 * @generated
	 * @ordered
	 */
	protected static final SchedulingPolicy SCHED_POLICY_EDEFAULT = SchedulingPolicy.FIFO;

	/**
	 * The cached value of the '{@link #getSchedPolicy() <em>Sched Policy</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSchedPolicy()
	 * @generated
	 * @ordered
	 */
	protected SchedulingPolicy schedPolicy = SCHED_POLICY_EDEFAULT;

	/**
	 * This is true if the Sched Policy attribute has been set.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 * @ordered
	 */
	protected boolean schedPolicyESet;

	/**
	 * The default value of the '{@link #getCore() <em>Core</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getCore()
	 * @generated
	 * @ordered
	 */
	protected static final int CORE_EDEFAULT = -1;

	/**
	 * The cached value of the '{@link #getCore() <em>Core</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getCore()
	 * @generated
	 * @ordered
	 */
	protected int core = CORE_EDEFAULT;

	/**
	 * The cached value of the '{@link #getModules() <em>Modules</em>}' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getModules()
	 * @generated
	 * @ordered
	 */
	protected EList<org.rsaml.model.Module> modules;

	/**
	 * The default value of the '{@link #getHost() <em>Host</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getHost()
	 * @generated
	 * @ordered
	 */
	protected static final String HOST_EDEFAULT = null;

	/**
	 * The cached value of the '{@link #getHost() <em>Host</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getHost()
	 * @generated
	 * @ordered
	 */
	protected String host = HOST_EDEFAULT;

	/**
	 * The default value of the '{@link #getLinkLatency() <em>Link Latency</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getLinkLatency()
	 * @generated
	 * @ordered
	 */
	protected static final double LINK_LATENCY_EDEFAULT = 0.0;

	/**
	 * The cached value of the '{@link #getLinkLatency() <em>Link Latency</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getLinkLatency()
	 * @generated
	 * @ordered
	 */
	protected double linkLatency = LINK_LATENCY_EDEFAULT;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected ProcessorImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.PROCESSOR;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public TimeUnit getTimeUnit() {
		return timeUnit;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setTimeUnit(TimeUnit newTimeUnit) {
		TimeUnit oldTimeUnit = timeUnit;
		timeUnit = newTimeUnit == null ? TIME_UNIT_EDEFAULT : newTimeUnit;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.PROCESSOR__TIME_UNIT, oldTimeUnit, timeUnit));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public SchedulingPolicy getSchedPolicy() {
		return schedPolicy;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setSchedPolicy(SchedulingPolicy newSchedPolicy) {
		SchedulingPolicy oldSchedPolicy = schedPolicy;
		schedPolicy = newSchedPolicy == null ? SCHED_POLICY_EDEFAULT : newSchedPolicy;
		boolean oldSchedPolicyESet = schedPolicyESet;
		schedPolicyESet = true;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.PROCESSOR__SCHED_POLICY, oldSchedPolicy, schedPolicy, !oldSchedPolicyESet));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void unsetSchedPolicy() {
		SchedulingPolicy oldSchedPolicy = schedPolicy;
		boolean oldSchedPolicyESet = schedPolicyESet;
		schedPolicy = SCHED_POLICY_EDEFAULT;
		schedPolicyESet = false;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.UNSET, RsamlPackage.PROCESSOR__SCHED_POLICY, oldSchedPolicy, SCHED_POLICY_EDEFAULT, oldSchedPolicyESet));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public boolean isSetSchedPolicy() {
		return schedPolicyESet;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public int getCore() {
		return core;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setCore(int newCore) {
		int oldCore = core;
		core = newCore;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.PROCESSOR__CORE, oldCore, core));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<org.rsaml.model.Module> getModules() {
		if (modules == null) {
			modules = new EObjectResolvingEList<org.rsaml.model.Module>(org.rsaml.model.Module.class, this, RsamlPackage.PROCESSOR__MODULES);
		}
		return modules;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public String getHost() {
		return host;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setHost(String newHost) {
		String oldHost = host;
		host = newHost;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.PROCESSOR__HOST, oldHost, host));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public double getLinkLatency() {
		return linkLatency;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setLinkLatency(double newLinkLatency) {
		double oldLinkLatency = linkLatency;
		linkLatency = newLinkLatency;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.PROCESSOR__LINK_LATENCY, oldLinkLatency, linkLatency));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public String packageProblem() {
		return org.rsaml.model.support.RsamlPackages.problem(this);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public double toMilliseconds(final double value) {
		return value * getTimeUnit().getValue() / 1000000.0;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public int compareTime(final double value, final TimeScaled other, final double otherValue) {
		return org.rsaml.model.support.RsamlTimes.compare(value, this, otherValue, other);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public boolean representable(final double value) {
		return org.rsaml.model.support.RsamlTimes.representable(value, this);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public boolean representablePeriod(final double value) {
		return org.rsaml.model.support.RsamlTimes.representablePeriod(value, this);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Object eGet(int featureID, boolean resolve, boolean coreType) {
		switch (featureID) {
			case RsamlPackage.PROCESSOR__TIME_UNIT:
				return getTimeUnit();
			case RsamlPackage.PROCESSOR__SCHED_POLICY:
				return getSchedPolicy();
			case RsamlPackage.PROCESSOR__CORE:
				return getCore();
			case RsamlPackage.PROCESSOR__MODULES:
				return getModules();
			case RsamlPackage.PROCESSOR__HOST:
				return getHost();
			case RsamlPackage.PROCESSOR__LINK_LATENCY:
				return getLinkLatency();
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
			case RsamlPackage.PROCESSOR__TIME_UNIT:
				setTimeUnit((TimeUnit)newValue);
				return;
			case RsamlPackage.PROCESSOR__SCHED_POLICY:
				setSchedPolicy((SchedulingPolicy)newValue);
				return;
			case RsamlPackage.PROCESSOR__CORE:
				setCore((Integer)newValue);
				return;
			case RsamlPackage.PROCESSOR__MODULES:
				getModules().clear();
				getModules().addAll((Collection<? extends org.rsaml.model.Module>)newValue);
				return;
			case RsamlPackage.PROCESSOR__HOST:
				setHost((String)newValue);
				return;
			case RsamlPackage.PROCESSOR__LINK_LATENCY:
				setLinkLatency((Double)newValue);
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
			case RsamlPackage.PROCESSOR__TIME_UNIT:
				setTimeUnit(TIME_UNIT_EDEFAULT);
				return;
			case RsamlPackage.PROCESSOR__SCHED_POLICY:
				unsetSchedPolicy();
				return;
			case RsamlPackage.PROCESSOR__CORE:
				setCore(CORE_EDEFAULT);
				return;
			case RsamlPackage.PROCESSOR__MODULES:
				getModules().clear();
				return;
			case RsamlPackage.PROCESSOR__HOST:
				setHost(HOST_EDEFAULT);
				return;
			case RsamlPackage.PROCESSOR__LINK_LATENCY:
				setLinkLatency(LINK_LATENCY_EDEFAULT);
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
			case RsamlPackage.PROCESSOR__TIME_UNIT:
				return timeUnit != TIME_UNIT_EDEFAULT;
			case RsamlPackage.PROCESSOR__SCHED_POLICY:
				return isSetSchedPolicy();
			case RsamlPackage.PROCESSOR__CORE:
				return core != CORE_EDEFAULT;
			case RsamlPackage.PROCESSOR__MODULES:
				return modules != null && !modules.isEmpty();
			case RsamlPackage.PROCESSOR__HOST:
				return HOST_EDEFAULT == null ? host != null : !HOST_EDEFAULT.equals(host);
			case RsamlPackage.PROCESSOR__LINK_LATENCY:
				return linkLatency != LINK_LATENCY_EDEFAULT;
		}
		return super.eIsSet(featureID);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public int eBaseStructuralFeatureID(int derivedFeatureID, Class<?> baseClass) {
		if (baseClass == TimeScaled.class) {
			switch (derivedFeatureID) {
				case RsamlPackage.PROCESSOR__TIME_UNIT: return RsamlPackage.TIME_SCALED__TIME_UNIT;
				default: return -1;
			}
		}
		return super.eBaseStructuralFeatureID(derivedFeatureID, baseClass);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public int eDerivedStructuralFeatureID(int baseFeatureID, Class<?> baseClass) {
		if (baseClass == TimeScaled.class) {
			switch (baseFeatureID) {
				case RsamlPackage.TIME_SCALED__TIME_UNIT: return RsamlPackage.PROCESSOR__TIME_UNIT;
				default: return -1;
			}
		}
		return super.eDerivedStructuralFeatureID(baseFeatureID, baseClass);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public int eDerivedOperationID(int baseOperationID, Class<?> baseClass) {
		if (baseClass == TimeScaled.class) {
			switch (baseOperationID) {
				case RsamlPackage.TIME_SCALED___TO_MILLISECONDS__DOUBLE: return RsamlPackage.PROCESSOR___TO_MILLISECONDS__DOUBLE;
				case RsamlPackage.TIME_SCALED___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE: return RsamlPackage.PROCESSOR___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE__DOUBLE: return RsamlPackage.PROCESSOR___REPRESENTABLE__DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE_PERIOD__DOUBLE: return RsamlPackage.PROCESSOR___REPRESENTABLE_PERIOD__DOUBLE;
				default: return -1;
			}
		}
		return super.eDerivedOperationID(baseOperationID, baseClass);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Object eInvoke(int operationID, EList<?> arguments) throws InvocationTargetException {
		switch (operationID) {
			case RsamlPackage.PROCESSOR___PACKAGE_PROBLEM:
				return packageProblem();
			case RsamlPackage.PROCESSOR___TO_MILLISECONDS__DOUBLE:
				return toMilliseconds((Double)arguments.get(0));
			case RsamlPackage.PROCESSOR___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE:
				return compareTime((Double)arguments.get(0), (TimeScaled)arguments.get(1), (Double)arguments.get(2));
			case RsamlPackage.PROCESSOR___REPRESENTABLE__DOUBLE:
				return representable((Double)arguments.get(0));
			case RsamlPackage.PROCESSOR___REPRESENTABLE_PERIOD__DOUBLE:
				return representablePeriod((Double)arguments.get(0));
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
		result.append(" (timeUnit: ");
		result.append(timeUnit);
		result.append(", schedPolicy: ");
		if (schedPolicyESet) result.append(schedPolicy); else result.append("<unset>");
		result.append(", core: ");
		result.append(core);
		result.append(", host: ");
		result.append(host);
		result.append(", linkLatency: ");
		result.append(linkLatency);
		result.append(')');
		return result.toString();
	}

} //ProcessorImpl
