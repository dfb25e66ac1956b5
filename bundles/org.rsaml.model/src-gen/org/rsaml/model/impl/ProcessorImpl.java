/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.impl;

import java.util.Collection;

import org.eclipse.emf.common.notify.Notification;

import org.eclipse.emf.common.util.EList;

import org.eclipse.emf.ecore.EClass;

import org.eclipse.emf.ecore.impl.ENotificationImpl;

import org.eclipse.emf.ecore.util.EObjectResolvingEList;

import org.rsaml.model.Processor;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.SchedulingPolicy;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Processor</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.ProcessorImpl#getSchedPolicy <em>Sched Policy</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ProcessorImpl#getCore <em>Core</em>}</li>
 *   <li>{@link org.rsaml.model.impl.ProcessorImpl#getModules <em>Modules</em>}</li>
 * </ul>
 *
 * @generated
 */
public class ProcessorImpl extends NamedElementImpl implements Processor {
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
	public Object eGet(int featureID, boolean resolve, boolean coreType) {
		switch (featureID) {
			case RsamlPackage.PROCESSOR__SCHED_POLICY:
				return getSchedPolicy();
			case RsamlPackage.PROCESSOR__CORE:
				return getCore();
			case RsamlPackage.PROCESSOR__MODULES:
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
			case RsamlPackage.PROCESSOR__SCHED_POLICY:
				unsetSchedPolicy();
				return;
			case RsamlPackage.PROCESSOR__CORE:
				setCore(CORE_EDEFAULT);
				return;
			case RsamlPackage.PROCESSOR__MODULES:
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
			case RsamlPackage.PROCESSOR__SCHED_POLICY:
				return isSetSchedPolicy();
			case RsamlPackage.PROCESSOR__CORE:
				return core != CORE_EDEFAULT;
			case RsamlPackage.PROCESSOR__MODULES:
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
	public String toString() {
		if (eIsProxy()) return super.toString();

		StringBuilder result = new StringBuilder(super.toString());
		result.append(" (schedPolicy: ");
		if (schedPolicyESet) result.append(schedPolicy); else result.append("<unset>");
		result.append(", core: ");
		result.append(core);
		result.append(')');
		return result.toString();
	}

} //ProcessorImpl
