/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.impl;

import java.lang.reflect.InvocationTargetException;

import org.eclipse.emf.common.notify.Notification;

import org.eclipse.emf.common.util.EList;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.InternalEObject;

import org.eclipse.emf.ecore.impl.ENotificationImpl;

import org.rsaml.model.OutputPort;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Subsumption Link</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.SubsumptionLinkImpl#getTimeUnit <em>Time Unit</em>}</li>
 *   <li>{@link org.rsaml.model.impl.SubsumptionLinkImpl#getTrigger <em>Trigger</em>}</li>
 *   <li>{@link org.rsaml.model.impl.SubsumptionLinkImpl#getDuration <em>Duration</em>}</li>
 * </ul>
 *
 * @generated
 */
public abstract class SubsumptionLinkImpl extends NamedElementImpl implements SubsumptionLink {
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
	 * The cached value of the '{@link #getTrigger() <em>Trigger</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getTrigger()
	 * @generated
	 * @ordered
	 */
	protected OutputPort trigger;

	/**
	 * The default value of the '{@link #getDuration() <em>Duration</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getDuration()
	 * @generated
	 * @ordered
	 */
	protected static final double DURATION_EDEFAULT = 0.0;

	/**
	 * The cached value of the '{@link #getDuration() <em>Duration</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getDuration()
	 * @generated
	 * @ordered
	 */
	protected double duration = DURATION_EDEFAULT;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected SubsumptionLinkImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.SUBSUMPTION_LINK;
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
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.SUBSUMPTION_LINK__TIME_UNIT, oldTimeUnit, timeUnit));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public OutputPort getTrigger() {
		if (trigger != null && trigger.eIsProxy()) {
			InternalEObject oldTrigger = (InternalEObject)trigger;
			trigger = (OutputPort)eResolveProxy(oldTrigger);
			if (trigger != oldTrigger) {
				if (eNotificationRequired())
					eNotify(new ENotificationImpl(this, Notification.RESOLVE, RsamlPackage.SUBSUMPTION_LINK__TRIGGER, oldTrigger, trigger));
			}
		}
		return trigger;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public OutputPort basicGetTrigger() {
		return trigger;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setTrigger(OutputPort newTrigger) {
		OutputPort oldTrigger = trigger;
		trigger = newTrigger;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.SUBSUMPTION_LINK__TRIGGER, oldTrigger, trigger));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public double getDuration() {
		return duration;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setDuration(double newDuration) {
		double oldDuration = duration;
		duration = newDuration;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.SUBSUMPTION_LINK__DURATION, oldDuration, duration));
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
			case RsamlPackage.SUBSUMPTION_LINK__TIME_UNIT:
				return getTimeUnit();
			case RsamlPackage.SUBSUMPTION_LINK__TRIGGER:
				if (resolve) return getTrigger();
				return basicGetTrigger();
			case RsamlPackage.SUBSUMPTION_LINK__DURATION:
				return getDuration();
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
			case RsamlPackage.SUBSUMPTION_LINK__TIME_UNIT:
				setTimeUnit((TimeUnit)newValue);
				return;
			case RsamlPackage.SUBSUMPTION_LINK__TRIGGER:
				setTrigger((OutputPort)newValue);
				return;
			case RsamlPackage.SUBSUMPTION_LINK__DURATION:
				setDuration((Double)newValue);
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
			case RsamlPackage.SUBSUMPTION_LINK__TIME_UNIT:
				setTimeUnit(TIME_UNIT_EDEFAULT);
				return;
			case RsamlPackage.SUBSUMPTION_LINK__TRIGGER:
				setTrigger((OutputPort)null);
				return;
			case RsamlPackage.SUBSUMPTION_LINK__DURATION:
				setDuration(DURATION_EDEFAULT);
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
			case RsamlPackage.SUBSUMPTION_LINK__TIME_UNIT:
				return timeUnit != TIME_UNIT_EDEFAULT;
			case RsamlPackage.SUBSUMPTION_LINK__TRIGGER:
				return trigger != null;
			case RsamlPackage.SUBSUMPTION_LINK__DURATION:
				return duration != DURATION_EDEFAULT;
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
				case RsamlPackage.SUBSUMPTION_LINK__TIME_UNIT: return RsamlPackage.TIME_SCALED__TIME_UNIT;
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
				case RsamlPackage.TIME_SCALED__TIME_UNIT: return RsamlPackage.SUBSUMPTION_LINK__TIME_UNIT;
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
				case RsamlPackage.TIME_SCALED___TO_MILLISECONDS__DOUBLE: return RsamlPackage.SUBSUMPTION_LINK___TO_MILLISECONDS__DOUBLE;
				case RsamlPackage.TIME_SCALED___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE: return RsamlPackage.SUBSUMPTION_LINK___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE__DOUBLE: return RsamlPackage.SUBSUMPTION_LINK___REPRESENTABLE__DOUBLE;
				case RsamlPackage.TIME_SCALED___REPRESENTABLE_PERIOD__DOUBLE: return RsamlPackage.SUBSUMPTION_LINK___REPRESENTABLE_PERIOD__DOUBLE;
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
			case RsamlPackage.SUBSUMPTION_LINK___TO_MILLISECONDS__DOUBLE:
				return toMilliseconds((Double)arguments.get(0));
			case RsamlPackage.SUBSUMPTION_LINK___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE:
				return compareTime((Double)arguments.get(0), (TimeScaled)arguments.get(1), (Double)arguments.get(2));
			case RsamlPackage.SUBSUMPTION_LINK___REPRESENTABLE__DOUBLE:
				return representable((Double)arguments.get(0));
			case RsamlPackage.SUBSUMPTION_LINK___REPRESENTABLE_PERIOD__DOUBLE:
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
		result.append(", duration: ");
		result.append(duration);
		result.append(')');
		return result.toString();
	}

} //SubsumptionLinkImpl
