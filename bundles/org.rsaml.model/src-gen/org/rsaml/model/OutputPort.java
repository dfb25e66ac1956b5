/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Output Port</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * An output port: the module sends data through it.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.OutputPort#getOutgoing <em>Outgoing</em>}</li>
 *   <li>{@link org.rsaml.model.OutputPort#getInhibitedBy <em>Inhibited By</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getOutputPort()
 * @model
 * @generated
 */
public interface OutputPort extends Port {
	/**
	 * Returns the value of the '<em><b>Outgoing</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Connection}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Connection#getSource <em>Source</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The connections that carry data from this output port.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Outgoing</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getOutputPort_Outgoing()
	 * @see org.rsaml.model.Connection#getSource
	 * @model opposite="source" transient="true"
	 * @generated
	 */
	EList<Connection> getOutgoing();

	/**
	 * Returns the value of the '<em><b>Inhibited By</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Inhibitor}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Inhibitor#getTarget <em>Target</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The inhibitors that can block the data leaving this output port.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Inhibited By</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getOutputPort_InhibitedBy()
	 * @see org.rsaml.model.Inhibitor#getTarget
	 * @model opposite="target" transient="true"
	 * @generated
	 */
	EList<Inhibitor> getInhibitedBy();

} // OutputPort
