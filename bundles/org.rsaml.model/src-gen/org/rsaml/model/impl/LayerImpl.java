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
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.util.InternalEList;

import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Layer</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.LayerImpl#getTimeUnit <em>Time Unit</em>}</li>
 *   <li>{@link org.rsaml.model.impl.LayerImpl#getArchitecture <em>Architecture</em>}</li>
 *   <li>{@link org.rsaml.model.impl.LayerImpl#getLevel <em>Level</em>}</li>
 *   <li>{@link org.rsaml.model.impl.LayerImpl#getMaxExecTime <em>Max Exec Time</em>}</li>
 *   <li>{@link org.rsaml.model.impl.LayerImpl#getModules <em>Modules</em>}</li>
 * </ul>
 *
 * @generated
 */
public class LayerImpl extends NamedElementImpl implements Layer {
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
	 * The default value of the '{@link #getLevel() <em>Level</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getLevel()
	 * @generated
	 * @ordered
	 */
	protected static final int LEVEL_EDEFAULT = 0;

	/**
	 * The cached value of the '{@link #getLevel() <em>Level</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getLevel()
	 * @generated
	 * @ordered
	 */
	protected int level = LEVEL_EDEFAULT;

	/**
	 * The default value of the '{@link #getMaxExecTime() <em>Max Exec Time</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getMaxExecTime()
	 * @generated
	 * @ordered
	 */
	protected static final double MAX_EXEC_TIME_EDEFAULT = 0.0;

	/**
	 * The cached value of the '{@link #getMaxExecTime() <em>Max Exec Time</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getMaxExecTime()
	 * @generated
	 * @ordered
	 */
	protected double maxExecTime = MAX_EXEC_TIME_EDEFAULT;

	/**
	 * The cached value of the '{@link #getModules() <em>Modules</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getModules()
	 * @generated
	 * @ordered
	 */
	protected EList<org.rsaml.model.Module> modules;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected LayerImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.LAYER;
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
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.LAYER__TIME_UNIT, oldTimeUnit, timeUnit));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Architecture getArchitecture() {
		if (eContainerFeatureID() != RsamlPackage.LAYER__ARCHITECTURE) return null;
		return (Architecture)eInternalContainer();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public NotificationChain basicSetArchitecture(Architecture newArchitecture, NotificationChain msgs) {
		msgs = eBasicSetContainer((InternalEObject)newArchitecture, RsamlPackage.LAYER__ARCHITECTURE, msgs);
		return msgs;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setArchitecture(Architecture newArchitecture) {
		if (newArchitecture != eInternalContainer() || (eContainerFeatureID() != RsamlPackage.LAYER__ARCHITECTURE && newArchitecture != null)) {
			if (EcoreUtil.isAncestor(this, newArchitecture))
				throw new IllegalArgumentException("Recursive containment not allowed for " + toString());
			NotificationChain msgs = null;
			if (eInternalContainer() != null)
				msgs = eBasicRemoveFromContainer(msgs);
			if (newArchitecture != null)
				msgs = ((InternalEObject)newArchitecture).eInverseAdd(this, RsamlPackage.ARCHITECTURE__LAYERS, Architecture.class, msgs);
			msgs = basicSetArchitecture(newArchitecture, msgs);
			if (msgs != null) msgs.dispatch();
		}
		else if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.LAYER__ARCHITECTURE, newArchitecture, newArchitecture));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public int getLevel() {
		return level;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setLevel(int newLevel) {
		int oldLevel = level;
		level = newLevel;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.LAYER__LEVEL, oldLevel, level));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public double getMaxExecTime() {
		return maxExecTime;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setMaxExecTime(double newMaxExecTime) {
		double oldMaxExecTime = maxExecTime;
		maxExecTime = newMaxExecTime;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.LAYER__MAX_EXEC_TIME, oldMaxExecTime, maxExecTime));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<org.rsaml.model.Module> getModules() {
		if (modules == null) {
			modules = new EObjectContainmentWithInverseEList<org.rsaml.model.Module>(org.rsaml.model.Module.class, this, RsamlPackage.LAYER__MODULES, RsamlPackage.MODULE__LAYER);
		}
		return modules;
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
	@SuppressWarnings("unchecked")
	@Override
	public NotificationChain eInverseAdd(InternalEObject otherEnd, int featureID, NotificationChain msgs) {
		switch (featureID) {
			case RsamlPackage.LAYER__ARCHITECTURE:
				if (eInternalContainer() != null)
					msgs = eBasicRemoveFromContainer(msgs);
				return basicSetArchitecture((Architecture)otherEnd, msgs);
			case RsamlPackage.LAYER__MODULES:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getModules()).basicAdd(otherEnd, msgs);
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
			case RsamlPackage.LAYER__ARCHITECTURE:
				return basicSetArchitecture(null, msgs);
			case RsamlPackage.LAYER__MODULES:
				return ((InternalEList<?>)getModules()).basicRemove(otherEnd, msgs);
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
			case RsamlPackage.LAYER__ARCHITECTURE:
				return eInternalContainer().eInverseRemove(this, RsamlPackage.ARCHITECTURE__LAYERS, Architecture.class, msgs);
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
			case RsamlPackage.LAYER__TIME_UNIT:
				return getTimeUnit();
			case RsamlPackage.LAYER__ARCHITECTURE:
				return getArchitecture();
			case RsamlPackage.LAYER__LEVEL:
				return getLevel();
			case RsamlPackage.LAYER__MAX_EXEC_TIME:
				return getMaxExecTime();
			case RsamlPackage.LAYER__MODULES:
				return getModules();
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
			case RsamlPackage.LAYER__TIME_UNIT:
				setTimeUnit((TimeUnit)newValue);
				return;
			case RsamlPackage.LAYER__ARCHITECTURE:
				setArchitecture((Architecture)newValue);
				return;
			case RsamlPackage.LAYER__LEVEL:
				setLevel((Integer)newValue);
				return;
			case RsamlPackage.LAYER__MAX_EXEC_TIME:
				setMaxExecTime((Double)newValue);
				return;
			case RsamlPackage.LAYER__MODULES:
				getModules().clear();
				getModules().addAll((Collection<? extends org.rsaml.model.Module>)newValue);
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
			case RsamlPackage.LAYER__TIME_UNIT:
				setTimeUnit(TIME_UNIT_EDEFAULT);
				return;
			case RsamlPackage.LAYER__ARCHITECTURE:
				setArchitecture((Architecture)null);
				return;
			case RsamlPackage.LAYER__LEVEL:
				setLevel(LEVEL_EDEFAULT);
				return;
			case RsamlPackage.LAYER__MAX_EXEC_TIME:
				setMaxExecTime(MAX_EXEC_TIME_EDEFAULT);
				return;
			case RsamlPackage.LAYER__MODULES:
				getModules().clear();
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
			case RsamlPackage.LAYER__TIME_UNIT:
				return timeUnit != TIME_UNIT_EDEFAULT;
			case RsamlPackage.LAYER__ARCHITECTURE:
				return getArchitecture() != null;
			case RsamlPackage.LAYER__LEVEL:
				return level != LEVEL_EDEFAULT;
			case RsamlPackage.LAYER__MAX_EXEC_TIME:
				return maxExecTime != MAX_EXEC_TIME_EDEFAULT;
			case RsamlPackage.LAYER__MODULES:
				return modules != null && !modules.isEmpty();
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
				case RsamlPackage.LAYER__TIME_UNIT: return RsamlPackage.TIME_SCALED__TIME_UNIT;
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
				case RsamlPackage.TIME_SCALED__TIME_UNIT: return RsamlPackage.LAYER__TIME_UNIT;
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
				case RsamlPackage.TIME_SCALED___TO_MILLISECONDS__DOUBLE: return RsamlPackage.LAYER___TO_MILLISECONDS__DOUBLE;
				case RsamlPackage.TIME_SCALED___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE: return RsamlPackage.LAYER___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE__DOUBLE: return RsamlPackage.LAYER___REPRESENTABLE__DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE_PERIOD__DOUBLE: return RsamlPackage.LAYER___REPRESENTABLE_PERIOD__DOUBLE;
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
			case RsamlPackage.LAYER___PACKAGE_PROBLEM:
				return packageProblem();
			case RsamlPackage.LAYER___TO_MILLISECONDS__DOUBLE:
				return toMilliseconds((Double)arguments.get(0));
			case RsamlPackage.LAYER___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE:
				return compareTime((Double)arguments.get(0), (TimeScaled)arguments.get(1), (Double)arguments.get(2));
			case RsamlPackage.LAYER___REPRESENTABLE__DOUBLE:
				return representable((Double)arguments.get(0));
			case RsamlPackage.LAYER___REPRESENTABLE_PERIOD__DOUBLE:
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
		result.append(", level: ");
		result.append(level);
		result.append(", maxExecTime: ");
		result.append(maxExecTime);
		result.append(')');
		return result.toString();
	}

} //LayerImpl
