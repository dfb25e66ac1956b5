/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.impl;

import java.util.Collection;

import org.eclipse.emf.common.notify.NotificationChain;

import org.eclipse.emf.common.util.EList;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.InternalEObject;

import org.eclipse.emf.ecore.util.EObjectWithInverseResolvingEList;
import org.eclipse.emf.ecore.util.InternalEList;

import org.rsaml.model.Connection;
import org.rsaml.model.EntryPort;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.Suppressor;

/**
 * <!-- begin-user-doc -->
 * An implementation of the model object '<em><b>Entry Port</b></em>'.
 * <!-- end-user-doc -->
 * <p>
 * The following features are implemented:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.impl.EntryPortImpl#getIncoming <em>Incoming</em>}</li>
 *   <li>{@link org.rsaml.model.impl.EntryPortImpl#getSuppressedBy <em>Suppressed By</em>}</li>
 * </ul>
 *
 * @generated
 */
public class EntryPortImpl extends PortImpl implements EntryPort {
	/**
	 * The cached value of the '{@link #getIncoming() <em>Incoming</em>}' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getIncoming()
	 * @generated
	 * @ordered
	 */
	protected EList<Connection> incoming;

	/**
	 * The cached value of the '{@link #getSuppressedBy() <em>Suppressed By</em>}' reference list.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #getSuppressedBy()
	 * @generated
	 * @ordered
	 */
	protected EList<Suppressor> suppressedBy;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected EntryPortImpl() {
		super();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EClass eStaticClass() {
		return RsamlPackage.Literals.ENTRY_PORT;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Connection> getIncoming() {
		if (incoming == null) {
			incoming = new EObjectWithInverseResolvingEList<Connection>(Connection.class, this, RsamlPackage.ENTRY_PORT__INCOMING, RsamlPackage.CONNECTION__TARGET);
		}
		return incoming;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EList<Suppressor> getSuppressedBy() {
		if (suppressedBy == null) {
			suppressedBy = new EObjectWithInverseResolvingEList<Suppressor>(Suppressor.class, this, RsamlPackage.ENTRY_PORT__SUPPRESSED_BY, RsamlPackage.SUPPRESSOR__TARGET);
		}
		return suppressedBy;
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
			case RsamlPackage.ENTRY_PORT__INCOMING:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getIncoming()).basicAdd(otherEnd, msgs);
			case RsamlPackage.ENTRY_PORT__SUPPRESSED_BY:
				return ((InternalEList<InternalEObject>)(InternalEList<?>)getSuppressedBy()).basicAdd(otherEnd, msgs);
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
			case RsamlPackage.ENTRY_PORT__INCOMING:
				return ((InternalEList<?>)getIncoming()).basicRemove(otherEnd, msgs);
			case RsamlPackage.ENTRY_PORT__SUPPRESSED_BY:
				return ((InternalEList<?>)getSuppressedBy()).basicRemove(otherEnd, msgs);
		}
		return super.eInverseRemove(otherEnd, featureID, msgs);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Object eGet(int featureID, boolean resolve, boolean coreType) {
		switch (featureID) {
			case RsamlPackage.ENTRY_PORT__INCOMING:
				return getIncoming();
			case RsamlPackage.ENTRY_PORT__SUPPRESSED_BY:
				return getSuppressedBy();
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
			case RsamlPackage.ENTRY_PORT__INCOMING:
				getIncoming().clear();
				getIncoming().addAll((Collection<? extends Connection>)newValue);
				return;
			case RsamlPackage.ENTRY_PORT__SUPPRESSED_BY:
				getSuppressedBy().clear();
				getSuppressedBy().addAll((Collection<? extends Suppressor>)newValue);
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
			case RsamlPackage.ENTRY_PORT__INCOMING:
				getIncoming().clear();
				return;
			case RsamlPackage.ENTRY_PORT__SUPPRESSED_BY:
				getSuppressedBy().clear();
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
			case RsamlPackage.ENTRY_PORT__INCOMING:
				return incoming != null && !incoming.isEmpty();
			case RsamlPackage.ENTRY_PORT__SUPPRESSED_BY:
				return suppressedBy != null && !suppressedBy.isEmpty();
		}
		return super.eIsSet(featureID);
	}

} //EntryPortImpl
