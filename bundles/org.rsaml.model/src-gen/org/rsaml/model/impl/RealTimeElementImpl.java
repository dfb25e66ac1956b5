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

import org.rsaml.model.ElementType;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Real Time Element</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.RealTimeElementImpl#getTimeUnit <em>Time Unit</em>}</li>
 *   <li>{@link org.rsaml.model.impl.RealTimeElementImpl#getType <em>Type</em>}</li>
 *   <li>{@link org.rsaml.model.impl.RealTimeElementImpl#getPeriod <em>Period</em>}</li>
 *   <li>{@link org.rsaml.model.impl.RealTimeElementImpl#getDelay <em>Delay</em>}</li>
 *   <li>{@link org.rsaml.model.impl.RealTimeElementImpl#getExecDuration <em>Exec Duration</em>}</li>
 *   <li>{@link org.rsaml.model.impl.RealTimeElementImpl#getExecType <em>Exec Type</em>}</li>
 * </ul>
 *
 * @generated
 */
public abstract class RealTimeElementImpl extends NamedElementImpl implements RealTimeElement {
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
	 * The default value of the '{@link #getType() <em>Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getType()
	 * @generated
	 * @ordered
	 */
	protected static final ElementType TYPE_EDEFAULT = ElementType.SIMPLE;

	/**
	 * The cached value of the '{@link #getType() <em>Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getType()
	 * @generated
	 * @ordered
	 */
	protected ElementType type = TYPE_EDEFAULT;

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
	 * The default value of the '{@link #getDelay() <em>Delay</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getDelay()
	 * @generated
	 * @ordered
	 */
	protected static final double DELAY_EDEFAULT = 0.0;

	/**
	 * The cached value of the '{@link #getDelay() <em>Delay</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getDelay()
	 * @generated
	 * @ordered
	 */
	protected double delay = DELAY_EDEFAULT;

	/**
	 * The default value of the '{@link #getExecDuration() <em>Exec Duration</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getExecDuration()
	 * @generated
	 * @ordered
	 */
	protected static final double EXEC_DURATION_EDEFAULT = 0.0;

	/**
	 * The cached value of the '{@link #getExecDuration() <em>Exec Duration</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getExecDuration()
	 * @generated
	 * @ordered
	 */
	protected double execDuration = EXEC_DURATION_EDEFAULT;

	/**
	 * The default value of the '{@link #getExecType() <em>Exec Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getExecType()
	 * @generated
	 * @ordered
	 */
	protected static final ExecutionType EXEC_TYPE_EDEFAULT = ExecutionType.APERIODIC;

	/**
	 * The cached value of the '{@link #getExecType() <em>Exec Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getExecType()
	 * @generated
	 * @ordered
	 */
	protected ExecutionType execType = EXEC_TYPE_EDEFAULT;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected RealTimeElementImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.REAL_TIME_ELEMENT;
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
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.REAL_TIME_ELEMENT__TIME_UNIT, oldTimeUnit, timeUnit));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public ElementType getType() {
		return type;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setType(ElementType newType) {
		ElementType oldType = type;
		type = newType == null ? TYPE_EDEFAULT : newType;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.REAL_TIME_ELEMENT__TYPE, oldType, type));
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
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.REAL_TIME_ELEMENT__PERIOD, oldPeriod, period));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public double getDelay() {
		return delay;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setDelay(double newDelay) {
		double oldDelay = delay;
		delay = newDelay;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.REAL_TIME_ELEMENT__DELAY, oldDelay, delay));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public double getExecDuration() {
		return execDuration;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setExecDuration(double newExecDuration) {
		double oldExecDuration = execDuration;
		execDuration = newExecDuration;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.REAL_TIME_ELEMENT__EXEC_DURATION, oldExecDuration, execDuration));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public ExecutionType getExecType() {
		return execType;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setExecType(ExecutionType newExecType) {
		ExecutionType oldExecType = execType;
		execType = newExecType == null ? EXEC_TYPE_EDEFAULT : newExecType;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.REAL_TIME_ELEMENT__EXEC_TYPE, oldExecType, execType));
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
			case RsamlPackage.REAL_TIME_ELEMENT__TIME_UNIT:
				return getTimeUnit();
			case RsamlPackage.REAL_TIME_ELEMENT__TYPE:
				return getType();
			case RsamlPackage.REAL_TIME_ELEMENT__PERIOD:
				return getPeriod();
			case RsamlPackage.REAL_TIME_ELEMENT__DELAY:
				return getDelay();
			case RsamlPackage.REAL_TIME_ELEMENT__EXEC_DURATION:
				return getExecDuration();
			case RsamlPackage.REAL_TIME_ELEMENT__EXEC_TYPE:
				return getExecType();
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
			case RsamlPackage.REAL_TIME_ELEMENT__TIME_UNIT:
				setTimeUnit((TimeUnit)newValue);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__TYPE:
				setType((ElementType)newValue);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__PERIOD:
				setPeriod((Double)newValue);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__DELAY:
				setDelay((Double)newValue);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__EXEC_DURATION:
				setExecDuration((Double)newValue);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__EXEC_TYPE:
				setExecType((ExecutionType)newValue);
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
			case RsamlPackage.REAL_TIME_ELEMENT__TIME_UNIT:
				setTimeUnit(TIME_UNIT_EDEFAULT);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__TYPE:
				setType(TYPE_EDEFAULT);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__PERIOD:
				setPeriod(PERIOD_EDEFAULT);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__DELAY:
				setDelay(DELAY_EDEFAULT);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__EXEC_DURATION:
				setExecDuration(EXEC_DURATION_EDEFAULT);
				return;
			case RsamlPackage.REAL_TIME_ELEMENT__EXEC_TYPE:
				setExecType(EXEC_TYPE_EDEFAULT);
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
			case RsamlPackage.REAL_TIME_ELEMENT__TIME_UNIT:
				return timeUnit != TIME_UNIT_EDEFAULT;
			case RsamlPackage.REAL_TIME_ELEMENT__TYPE:
				return type != TYPE_EDEFAULT;
			case RsamlPackage.REAL_TIME_ELEMENT__PERIOD:
				return period != PERIOD_EDEFAULT;
			case RsamlPackage.REAL_TIME_ELEMENT__DELAY:
				return delay != DELAY_EDEFAULT;
			case RsamlPackage.REAL_TIME_ELEMENT__EXEC_DURATION:
				return execDuration != EXEC_DURATION_EDEFAULT;
			case RsamlPackage.REAL_TIME_ELEMENT__EXEC_TYPE:
				return execType != EXEC_TYPE_EDEFAULT;
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
				case RsamlPackage.REAL_TIME_ELEMENT__TIME_UNIT: return RsamlPackage.TIME_SCALED__TIME_UNIT;
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
				case RsamlPackage.TIME_SCALED__TIME_UNIT: return RsamlPackage.REAL_TIME_ELEMENT__TIME_UNIT;
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
				case RsamlPackage.TIME_SCALED___TO_MILLISECONDS__DOUBLE: return RsamlPackage.REAL_TIME_ELEMENT___TO_MILLISECONDS__DOUBLE;
				case RsamlPackage.TIME_SCALED___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE: return RsamlPackage.REAL_TIME_ELEMENT___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE__DOUBLE: return RsamlPackage.REAL_TIME_ELEMENT___REPRESENTABLE__DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE_PERIOD__DOUBLE: return RsamlPackage.REAL_TIME_ELEMENT___REPRESENTABLE_PERIOD__DOUBLE;
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
			case RsamlPackage.REAL_TIME_ELEMENT___TO_MILLISECONDS__DOUBLE:
				return toMilliseconds((Double)arguments.get(0));
			case RsamlPackage.REAL_TIME_ELEMENT___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE:
				return compareTime((Double)arguments.get(0), (TimeScaled)arguments.get(1), (Double)arguments.get(2));
			case RsamlPackage.REAL_TIME_ELEMENT___REPRESENTABLE__DOUBLE:
				return representable((Double)arguments.get(0));
			case RsamlPackage.REAL_TIME_ELEMENT___REPRESENTABLE_PERIOD__DOUBLE:
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
		result.append(", type: ");
		result.append(type);
		result.append(", period: ");
		result.append(period);
		result.append(", delay: ");
		result.append(delay);
		result.append(", execDuration: ");
		result.append(execDuration);
		result.append(", execType: ");
		result.append(execType);
		result.append(')');
		return result.toString();
	}

} //RealTimeElementImpl
