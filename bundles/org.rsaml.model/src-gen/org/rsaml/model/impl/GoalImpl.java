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

import org.rsaml.model.Goal;
import org.rsaml.model.Mission;
import org.rsaml.model.RsamlPackage;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Goal</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.GoalImpl#getMission <em>Mission</em>}</li>
 *   <li>{@link org.rsaml.model.impl.GoalImpl#getParentGoal <em>Parent Goal</em>}</li>
 *   <li>{@link org.rsaml.model.impl.GoalImpl#getSubGoals <em>Sub Goals</em>}</li>
 *   <li>{@link org.rsaml.model.impl.GoalImpl#getPriority <em>Priority</em>}</li>
 * </ul>
 *
 * @generated
 */
public class GoalImpl extends NamedElementImpl implements Goal {
	/**
	 * The cached value of the '{@link #getSubGoals() <em>Sub Goals</em>}' containment reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSubGoals()
	 * @generated
	 * @ordered
	 */
	protected EList<Goal> subGoals;

	/**
	 * The default value of the '{@link #getPriority() <em>Priority</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getPriority()
	 * @generated
	 * @ordered
	 */
	protected static final int PRIORITY_EDEFAULT = 0;

	/**
	 * The cached value of the '{@link #getPriority() <em>Priority</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getPriority()
	 * @generated
	 * @ordered
	 */
	protected int priority = PRIORITY_EDEFAULT;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected GoalImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.GOAL;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Mission getMission() {
		if (eContainerFeatureID() != RsamlPackage.GOAL__MISSION) return null;
		return (Mission)eInternalContainer();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public NotificationChain basicSetMission(Mission newMission, NotificationChain msgs) {
		msgs = eBasicSetContainer((InternalEObject)newMission, RsamlPackage.GOAL__MISSION, msgs);
		return msgs;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setMission(Mission newMission) {
		if (newMission != eInternalContainer() || (eContainerFeatureID() != RsamlPackage.GOAL__MISSION && newMission != null)) {
			if (EcoreUtil.isAncestor(this, newMission))
				throw new IllegalArgumentException("Recursive containment not allowed for " + toString());
			NotificationChain msgs = null;
			if (eInternalContainer() != null)
				msgs = eBasicRemoveFromContainer(msgs);
			if (newMission != null)
				msgs = ((InternalEObject)newMission).eInverseAdd(this, RsamlPackage.MISSION__GOALS, Mission.class, msgs);
			msgs = basicSetMission(newMission, msgs);
			if (msgs != null) msgs.dispatch();
		}
		else if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.GOAL__MISSION, newMission, newMission));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Goal getParentGoal() {
		if (eContainerFeatureID() != RsamlPackage.GOAL__PARENT_GOAL) return null;
		return (Goal)eInternalContainer();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public NotificationChain basicSetParentGoal(Goal newParentGoal, NotificationChain msgs) {
		msgs = eBasicSetContainer((InternalEObject)newParentGoal, RsamlPackage.GOAL__PARENT_GOAL, msgs);
		return msgs;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setParentGoal(Goal newParentGoal) {
		if (newParentGoal != eInternalContainer() || (eContainerFeatureID() != RsamlPackage.GOAL__PARENT_GOAL && newParentGoal != null)) {
			if (EcoreUtil.isAncestor(this, newParentGoal))
				throw new IllegalArgumentException("Recursive containment not allowed for " + toString());
			NotificationChain msgs = null;
			if (eInternalContainer() != null)
				msgs = eBasicRemoveFromContainer(msgs);
			if (newParentGoal != null)
				msgs = ((InternalEObject)newParentGoal).eInverseAdd(this, RsamlPackage.GOAL__SUB_GOALS, Goal.class, msgs);
			msgs = basicSetParentGoal(newParentGoal, msgs);
			if (msgs != null) msgs.dispatch();
		}
		else if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.GOAL__PARENT_GOAL, newParentGoal, newParentGoal));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Goal> getSubGoals() {
		if (subGoals == null) {
			subGoals = new EObjectContainmentWithInverseEList<Goal>(Goal.class, this, RsamlPackage.GOAL__SUB_GOALS, RsamlPackage.GOAL__PARENT_GOAL);
		}
		return subGoals;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public int getPriority() {
		return priority;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void setPriority(int newPriority) {
		int oldPriority = priority;
		priority = newPriority;
		if (eNotificationRequired())
			eNotify(new ENotificationImpl(this, Notification.SET, RsamlPackage.GOAL__PRIORITY, oldPriority, priority));
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
			case RsamlPackage.GOAL__MISSION:
				if (eInternalContainer() != null)
					msgs = eBasicRemoveFromContainer(msgs);
				return basicSetMission((Mission)otherEnd, msgs);
			case RsamlPackage.GOAL__PARENT_GOAL:
				if (eInternalContainer() != null)
					msgs = eBasicRemoveFromContainer(msgs);
				return basicSetParentGoal((Goal)otherEnd, msgs);
			case RsamlPackage.GOAL__SUB_GOALS:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getSubGoals()).basicAdd(otherEnd, msgs);
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
			case RsamlPackage.GOAL__MISSION:
				return basicSetMission(null, msgs);
			case RsamlPackage.GOAL__PARENT_GOAL:
				return basicSetParentGoal(null, msgs);
			case RsamlPackage.GOAL__SUB_GOALS:
				return ((InternalEList<?>)getSubGoals()).basicRemove(otherEnd, msgs);
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
			case RsamlPackage.GOAL__MISSION:
				return eInternalContainer().eInverseRemove(this, RsamlPackage.MISSION__GOALS, Mission.class, msgs);
			case RsamlPackage.GOAL__PARENT_GOAL:
				return eInternalContainer().eInverseRemove(this, RsamlPackage.GOAL__SUB_GOALS, Goal.class, msgs);
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
			case RsamlPackage.GOAL__MISSION:
				return getMission();
			case RsamlPackage.GOAL__PARENT_GOAL:
				return getParentGoal();
			case RsamlPackage.GOAL__SUB_GOALS:
				return getSubGoals();
			case RsamlPackage.GOAL__PRIORITY:
				return getPriority();
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
			case RsamlPackage.GOAL__MISSION:
				setMission((Mission)newValue);
				return;
			case RsamlPackage.GOAL__PARENT_GOAL:
				setParentGoal((Goal)newValue);
				return;
			case RsamlPackage.GOAL__SUB_GOALS:
				getSubGoals().clear();
				getSubGoals().addAll((Collection<? extends Goal>)newValue);
				return;
			case RsamlPackage.GOAL__PRIORITY:
				setPriority((Integer)newValue);
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
			case RsamlPackage.GOAL__MISSION:
				setMission((Mission)null);
				return;
			case RsamlPackage.GOAL__PARENT_GOAL:
				setParentGoal((Goal)null);
				return;
			case RsamlPackage.GOAL__SUB_GOALS:
				getSubGoals().clear();
				return;
			case RsamlPackage.GOAL__PRIORITY:
				setPriority(PRIORITY_EDEFAULT);
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
			case RsamlPackage.GOAL__MISSION:
				return getMission() != null;
			case RsamlPackage.GOAL__PARENT_GOAL:
				return getParentGoal() != null;
			case RsamlPackage.GOAL__SUB_GOALS:
				return subGoals != null && !subGoals.isEmpty();
			case RsamlPackage.GOAL__PRIORITY:
				return priority != PRIORITY_EDEFAULT;
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
		result.append(" (priority: ");
		result.append(priority);
		result.append(')');
		return result.toString();
	}

} //GoalImpl
