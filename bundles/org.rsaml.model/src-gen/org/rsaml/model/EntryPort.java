/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Entry Port</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * An input port: the module receives data through it.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.EntryPort#getIncoming <em>Incoming</em>}</li>
 *   <li>{@link org.rsaml.model.EntryPort#getSuppressedBy <em>Suppressed By</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getEntryPort()
 * @model
 * @generated
 */
public interface EntryPort extends Port {
	/**
	 * Returns the value of the '<em><b>Incoming</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Connection}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Connection#getTarget <em>Target</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The connections that bring data to this entry port.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Incoming</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getEntryPort_Incoming()
	 * @see org.rsaml.model.Connection#getTarget
	 * @model opposite="target" transient="true"
	 * @generated
	 */
	EList<Connection> getIncoming();

	/**
	 * Returns the value of the '<em><b>Suppressed By</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Suppressor}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Suppressor#getTarget <em>Target</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The suppressors that can replace the data arriving at this entry port.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Suppressed By</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getEntryPort_SuppressedBy()
	 * @see org.rsaml.model.Suppressor#getTarget
	 * @model opposite="target" transient="true"
	 * @generated
	 */
	EList<Suppressor> getSuppressedBy();

} // EntryPort
