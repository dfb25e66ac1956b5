/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.impl;

import java.lang.reflect.InvocationTargetException;

import org.eclipse.emf.common.notify.Notification;

import org.eclipse.emf.common.util.EList;

import org.eclipse.emf.ecore.EClass;

import org.eclipse.emf.ecore.impl.ENotificationImpl;

import org.rsaml.model.DataType;
import org.rsaml.model.Device;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Device</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.DeviceImpl#getTimeUnit <em>Time Unit</em>}</li>
 *   <li>{@link org.rsaml.model.impl.DeviceImpl#getKind <em>Kind</em>}</li>
 *   <li>{@link org.rsaml.model.impl.DeviceImpl#getDataType <em>Data Type</em>}</li>
 *   <li>{@link org.rsaml.model.impl.DeviceImpl#getPeriod <em>Period</em>}</li>
 * </ul>
 *
 * @generated
 */
public abstract class DeviceImpl extends NamedElementImpl implements Device {
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
	 * The default value of the '{@link #getKind() <em>Kind</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getKind()
	 * @generated
	 * @ordered
	 */
	protected static final String KIND_EDEFAULT = null;

	/**
	 * The cached value of the '{@link #getKind() <em>Kind</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getKind()
	 * @generated
	 * @ordered
	 */
	protected String kind = KIND_EDEFAULT;

	/**
	 * The default value of the '{@link #getDataType() <em>Data Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getDataType()
	 * @generated
	 * @ordered
	 */
	protected static final DataType DATA_TYPE_EDEFAULT = DataType.NUMERIC;

	/**
	 * The cached value of the '{@link #getDataType() <em>Data Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getDataType()
	 * @generated
	 * @ordered
	 */
	protected DataType dataType = DATA_TYPE_EDEFAULT;

	/**
	 * The default value of the '{@link #getPeriod() <em>Period</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getPeriod()
	 * @generated
	 * @ordered
	 */
	protected static final double PERIOD_EDEFAULT = 0.0;

	/**
	 * The cached value of the '{@link #getPeriod() <em>Period</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getPeriod()
	 * @generated
	 * @ordered
	 */
	protected double period = PERIOD_EDEFAULT;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected DeviceImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.DEVICE;
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
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.DEVICE__TIME_UNIT, oldTimeUnit, timeUnit));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public String getKind() {
		return kind;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setKind(String newKind) {
		String oldKind = kind;
		kind = newKind;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.DEVICE__KIND, oldKind, kind));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public DataType getDataType() {
		return dataType;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setDataType(DataType newDataType) {
		DataType oldDataType = dataType;
		dataType = newDataType == null ? DATA_TYPE_EDEFAULT : newDataType;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.DEVICE__DATA_TYPE, oldDataType, dataType));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public double getPeriod() {
		return period;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setPeriod(double newPeriod) {
		double oldPeriod = period;
		period = newPeriod;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.DEVICE__PERIOD, oldPeriod, period));
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
			case RsamlPackage.DEVICE__TIME_UNIT:
				return getTimeUnit();
			case RsamlPackage.DEVICE__KIND:
				return getKind();
			case RsamlPackage.DEVICE__DATA_TYPE:
				return getDataType();
			case RsamlPackage.DEVICE__PERIOD:
				return getPeriod();
		}
		return super.eGet(featureID, resolve, coreType);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void eSet(int featureID, Object newValue) {
		switch (featureID) {
			case RsamlPackage.DEVICE__TIME_UNIT:
				setTimeUnit((TimeUnit)newValue);
				return;
			case RsamlPackage.DEVICE__KIND:
				setKind((String)newValue);
				return;
			case RsamlPackage.DEVICE__DATA_TYPE:
				setDataType((DataType)newValue);
				return;
			case RsamlPackage.DEVICE__PERIOD:
				setPeriod((Double)newValue);
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
			case RsamlPackage.DEVICE__TIME_UNIT:
				setTimeUnit(TIME_UNIT_EDEFAULT);
				return;
			case RsamlPackage.DEVICE__KIND:
				setKind(KIND_EDEFAULT);
				return;
			case RsamlPackage.DEVICE__DATA_TYPE:
				setDataType(DATA_TYPE_EDEFAULT);
				return;
			case RsamlPackage.DEVICE__PERIOD:
				setPeriod(PERIOD_EDEFAULT);
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
			case RsamlPackage.DEVICE__TIME_UNIT:
				return timeUnit != TIME_UNIT_EDEFAULT;
			case RsamlPackage.DEVICE__KIND:
				return KIND_EDEFAULT == null ? kind != null : !KIND_EDEFAULT.equals(kind);
			case RsamlPackage.DEVICE__DATA_TYPE:
				return dataType != DATA_TYPE_EDEFAULT;
			case RsamlPackage.DEVICE__PERIOD:
				return period != PERIOD_EDEFAULT;
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
				case RsamlPackage.DEVICE__TIME_UNIT: return RsamlPackage.TIME_SCALED__TIME_UNIT;
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
				case RsamlPackage.TIME_SCALED__TIME_UNIT: return RsamlPackage.DEVICE__TIME_UNIT;
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
				case RsamlPackage.TIME_SCALED___TO_MILLISECONDS__DOUBLE: return RsamlPackage.DEVICE___TO_MILLISECONDS__DOUBLE;
				case RsamlPackage.TIME_SCALED___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE: return RsamlPackage.DEVICE___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE__DOUBLE: return RsamlPackage.DEVICE___REPRESENTABLE__DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE_PERIOD__DOUBLE: return RsamlPackage.DEVICE___REPRESENTABLE_PERIOD__DOUBLE;
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
			case RsamlPackage.DEVICE___TO_MILLISECONDS__DOUBLE:
				return toMilliseconds((Double)arguments.get(0));
			case RsamlPackage.DEVICE___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE:
				return compareTime((Double)arguments.get(0), (TimeScaled)arguments.get(1), (Double)arguments.get(2));
			case RsamlPackage.DEVICE___REPRESENTABLE__DOUBLE:
				return representable((Double)arguments.get(0));
			case RsamlPackage.DEVICE___REPRESENTABLE_PERIOD__DOUBLE:
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
		result.append(", kind: ");
		result.append(kind);
		result.append(", dataType: ");
		result.append(dataType);
		result.append(", period: ");
		result.append(period);
		result.append(')');
		return result.toString();
	}

} //DeviceImpl
