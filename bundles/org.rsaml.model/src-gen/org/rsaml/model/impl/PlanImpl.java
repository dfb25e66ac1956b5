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
import org.eclipse.emf.ecore.util.EObjectResolvingEList;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.ecore.util.InternalEList;

import org.rsaml.model.Activity;
import org.rsaml.model.Goal;
import org.rsaml.model.Mission;
import org.rsaml.model.Plan;
import org.rsaml.model.RsamlPackage;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Plan</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.PlanImpl#getMission <em>Mission</em>}</li>
 *   <li>{@link org.rsaml.model.impl.PlanImpl#getActivities <em>Activities</em>}</li>
 *   <li>{@link org.rsaml.model.impl.PlanImpl#getAchieves <em>Achieves</em>}</li>
 * </ul>
 *
 * @generated
 */
public class PlanImpl extends NamedElementImpl implements Plan {
	/**
	 * The cached value of the '{@link #getActivities() <em>Activities</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getActivities()
	 * @generated
	 * @ordered
	 */
	protected EList<Activity> activities;

	/**
	 * The cached value of the '{@link #getAchieves() <em>Achieves</em>}' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getAchieves()
	 * @generated
	 * @ordered
	 */
	protected EList<Goal> achieves;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected PlanImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.PLAN;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Mission getMission() {
		if (eContainerFeatureID() != RsamlPackage.PLAN__MISSION) return null;
		return (Mission)eInternalContainer();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public NotificationChain basicSetMission(Mission newMission, NotificationChain msgs) {
		msgs = eBasicSetContainer((InternalEObject)newMission, RsamlPackage.PLAN__MISSION, msgs);
		return msgs;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setMission(Mission newMission) {
		if (newMission != eInternalContainer() || (eContainerFeatureID() != RsamlPackage.PLAN__MISSION && newMission != null)) {
			if (EcoreUtil.isAncestor(this, newMission))
				throw new IllegalArgumentException("Recursive containment not allowed for " + toString());
			NotificationChain msgs = null;
			if (eInternalContainer() != null)
				msgs = eBasicRemoveFromContainer(msgs);
			if (newMission != null)
				msgs = ((InternalEObject)newMission).eInverseAdd(this, RsamlPackage.MISSION__PLANS, Mission.class, msgs);
			msgs = basicSetMission(newMission, msgs);
			if (msgs != null) msgs.dispatch();
		}
		else if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.PLAN__MISSION, newMission, newMission));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Activity> getActivities() {
		if (activities == null) {
			activities = new EObjectContainmentWithInverseEList<Activity>(Activity.class, this, RsamlPackage.PLAN__ACTIVITIES, RsamlPackage.ACTIVITY__PLAN);
		}
		return activities;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Goal> getAchieves() {
		if (achieves == null) {
			achieves = new EObjectResolvingEList<Goal>(Goal.class, this, RsamlPackage.PLAN__ACHIEVES);
		}
		return achieves;
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
			case RsamlPackage.PLAN__MISSION:
				if (eInternalContainer() != null)
					msgs = eBasicRemoveFromContainer(msgs);
				return basicSetMission((Mission)otherEnd, msgs);
			case RsamlPackage.PLAN__ACTIVITIES:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getActivities()).basicAdd(otherEnd, msgs);
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
			case RsamlPackage.PLAN__MISSION:
				return basicSetMission(null, msgs);
			case RsamlPackage.PLAN__ACTIVITIES:
				return ((InternalEList<?>)getActivities()).basicRemove(otherEnd, msgs);
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
			case RsamlPackage.PLAN__MISSION:
				return eInternalContainer().eInverseRemove(this, RsamlPackage.MISSION__PLANS, Mission.class, msgs);
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
			case RsamlPackage.PLAN__MISSION:
				return getMission();
			case RsamlPackage.PLAN__ACTIVITIES:
				return getActivities();
			case RsamlPackage.PLAN__ACHIEVES:
				return getAchieves();
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
			case RsamlPackage.PLAN__MISSION:
				setMission((Mission)newValue);
				return;
			case RsamlPackage.PLAN__ACTIVITIES:
				getActivities().clear();
				getActivities().addAll((Collection<? extends Activity>)newValue);
				return;
			case RsamlPackage.PLAN__ACHIEVES:
				getAchieves().clear();
				getAchieves().addAll((Collection<? extends Goal>)newValue);
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
			case RsamlPackage.PLAN__MISSION:
				setMission((Mission)null);
				return;
			case RsamlPackage.PLAN__ACTIVITIES:
				getActivities().clear();
				return;
			case RsamlPackage.PLAN__ACHIEVES:
				getAchieves().clear();
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
			case RsamlPackage.PLAN__MISSION:
				return getMission() != null;
			case RsamlPackage.PLAN__ACTIVITIES:
				return activities != null && !activities.isEmpty();
			case RsamlPackage.PLAN__ACHIEVES:
				return achieves != null && !achieves.isEmpty();
		}
		return super.eIsSet(featureID);
	}

} //PlanImpl
