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

import org.eclipse.emf.ecore.util.EObjectContainmentWithInverseEList;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.util.InternalEList;

import org.rsaml.model.Action;
import org.rsaml.model.Function;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.SynchronisationType;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Function</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.FunctionImpl#getModule <em>Module</em>}</li>
 *   <li>{@link org.rsaml.model.impl.FunctionImpl#getActions <em>Actions</em>}</li>
 *   <li>{@link org.rsaml.model.impl.FunctionImpl#getSynchroType <em>Synchro Type</em>}</li>
 *   <li>{@link org.rsaml.model.impl.FunctionImpl#getSchedPolicy <em>Sched Policy</em>}</li>
 *   <li>{@link org.rsaml.model.impl.FunctionImpl#getOtherPolicy <em>Other Policy</em>}</li>
 * </ul>
 *
 * @generated
 */
public class FunctionImpl extends RealTimeElementImpl implements Function {
	/**
	 * The cached value of the '{@link #getActions() <em>Actions</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getActions()
	 * @generated
	 * @ordered
	 */
	protected EList<Action> actions;

	/**
	 * The default value of the '{@link #getSynchroType() <em>Synchro Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSynchroType()
	 * @generated
	 * @ordered
	 */
	protected static final SynchronisationType SYNCHRO_TYPE_EDEFAULT = SynchronisationType.SYNCHRONOUS;

	/**
	 * The cached value of the '{@link #getSynchroType() <em>Synchro Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSynchroType()
	 * @generated
	 * @ordered
	 */
	protected SynchronisationType synchroType = SYNCHRO_TYPE_EDEFAULT;

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
	 * The default value of the '{@link #getOtherPolicy() <em>Other Policy</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getOtherPolicy()
	 * @generated
	 * @ordered
	 */
	protected static final String OTHER_POLICY_EDEFAULT = null;

	/**
	 * The cached value of the '{@link #getOtherPolicy() <em>Other Policy</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getOtherPolicy()
	 * @generated
	 * @ordered
	 */
	protected String otherPolicy = OTHER_POLICY_EDEFAULT;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected FunctionImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.FUNCTION;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public org.rsaml.model.Module getModule() {
		if (eContainerFeatureID() != RsamlPackage.FUNCTION__MODULE) return null;
		return (org.rsaml.model.Module)eInternalContainer();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public NotificationChain basicSetModule(org.rsaml.model.Module newModule, NotificationChain msgs) {
		msgs = eBasicSetContainer((InternalEObject)newModule, RsamlPackage.FUNCTION__MODULE, msgs);
		return msgs;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setModule(org.rsaml.model.Module newModule) {
		if (newModule != eInternalContainer() || (eContainerFeatureID() != RsamlPackage.FUNCTION__MODULE && newModule != null)) {
			if (EcoreUtil.isAncestor(this, newModule))
				throw new IllegalArgumentException("Recursive containment not allowed for " + toString());
			NotificationChain msgs = null;
			if (eInternalContainer() != null)
				msgs = eBasicRemoveFromContainer(msgs);
			if (newModule != null)
				msgs = ((InternalEObject)newModule).eInverseAdd(this, RsamlPackage.MODULE__FUNCTIONS, org.rsaml.model.Module.class, msgs);
			msgs = basicSetModule(newModule, msgs);
			if (msgs != null) msgs.dispatch();
		}
		else if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.FUNCTION__MODULE, newModule, newModule));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Action> getActions() {
		if (actions == null) {
			actions = new EObjectContainmentWithInverseEList<Action>(Action.class, this, RsamlPackage.FUNCTION__ACTIONS, RsamlPackage.ACTION__FUNCTION);
		}
		return actions;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public SynchronisationType getSynchroType() {
		return synchroType;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setSynchroType(SynchronisationType newSynchroType) {
		SynchronisationType oldSynchroType = synchroType;
		synchroType = newSynchroType == null ? SYNCHRO_TYPE_EDEFAULT : newSynchroType;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.FUNCTION__SYNCHRO_TYPE, oldSynchroType, synchroType));
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
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.FUNCTION__SCHED_POLICY, oldSchedPolicy, schedPolicy));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public String getOtherPolicy() {
		return otherPolicy;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setOtherPolicy(String newOtherPolicy) {
		String oldOtherPolicy = otherPolicy;
		otherPolicy = newOtherPolicy;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.FUNCTION__OTHER_POLICY, oldOtherPolicy, otherPolicy));
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
			case RsamlPackage.FUNCTION__MODULE:
				if (eInternalContainer() != null)
					msgs = eBasicRemoveFromContainer(msgs);
				return basicSetModule((org.rsaml.model.Module)otherEnd, msgs);
			case RsamlPackage.FUNCTION__ACTIONS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getActions()).basicAdd(otherEnd, msgs);
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
			case RsamlPackage.FUNCTION__MODULE:
				return basicSetModule(null, msgs);
			case RsamlPackage.FUNCTION__ACTIONS:
				return ((InternalEList<?>)getActions()).basicRemove(otherEnd, msgs);
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
			case RsamlPackage.FUNCTION__MODULE:
				return eInternalContainer().eInverseRemove(this, RsamlPackage.MODULE__FUNCTIONS, org.rsaml.model.Module.class, msgs);
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
			case RsamlPackage.FUNCTION__MODULE:
				return getModule();
			case RsamlPackage.FUNCTION__ACTIONS:
				return getActions();
			case RsamlPackage.FUNCTION__SYNCHRO_TYPE:
				return getSynchroType();
			case RsamlPackage.FUNCTION__SCHED_POLICY:
				return getSchedPolicy();
			case RsamlPackage.FUNCTION__OTHER_POLICY:
				return getOtherPolicy();
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
			case RsamlPackage.FUNCTION__MODULE:
				setModule((org.rsaml.model.Module)newValue);
				return;
			case RsamlPackage.FUNCTION__ACTIONS:
				getActions().clear();
				getActions().addAll((Collection<? extends Action>)newValue);
				return;
			case RsamlPackage.FUNCTION__SYNCHRO_TYPE:
				setSynchroType((SynchronisationType)newValue);
				return;
			case RsamlPackage.FUNCTION__SCHED_POLICY:
				setSchedPolicy((SchedulingPolicy)newValue);
				return;
			case RsamlPackage.FUNCTION__OTHER_POLICY:
				setOtherPolicy((String)newValue);
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
			case RsamlPackage.FUNCTION__MODULE:
				setModule((org.rsaml.model.Module)null);
				return;
			case RsamlPackage.FUNCTION__ACTIONS:
				getActions().clear();
				return;
			case RsamlPackage.FUNCTION__SYNCHRO_TYPE:
				setSynchroType(SYNCHRO_TYPE_EDEFAULT);
				return;
			case RsamlPackage.FUNCTION__SCHED_POLICY:
				setSchedPolicy(SCHED_POLICY_EDEFAULT);
				return;
			case RsamlPackage.FUNCTION__OTHER_POLICY:
				setOtherPolicy(OTHER_POLICY_EDEFAULT);
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
			case RsamlPackage.FUNCTION__MODULE:
				return getModule() != null;
			case RsamlPackage.FUNCTION__ACTIONS:
				return actions != null && !actions.isEmpty();
			case RsamlPackage.FUNCTION__SYNCHRO_TYPE:
				return synchroType != SYNCHRO_TYPE_EDEFAULT;
			case RsamlPackage.FUNCTION__SCHED_POLICY:
				return schedPolicy != SCHED_POLICY_EDEFAULT;
			case RsamlPackage.FUNCTION__OTHER_POLICY:
				return OTHER_POLICY_EDEFAULT == null ? otherPolicy != null : !OTHER_POLICY_EDEFAULT.equals(otherPolicy);
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
		result.append(" (synchroType: ");
		result.append(synchroType);
		result.append(", schedPolicy: ");
		result.append(schedPolicy);
		result.append(", otherPolicy: ");
		result.append(otherPolicy);
		result.append(')');
		return result.toString();
	}

} //FunctionImpl
