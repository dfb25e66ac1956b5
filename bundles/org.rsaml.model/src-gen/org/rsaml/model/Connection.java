/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.ecore.EObject;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Connection</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A data flow from an output port of a module to an entry port of a module.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Connection#getArchitecture <em>Architecture</em>}</li>
 *   <li>{@link org.rsaml.model.Connection#getSource <em>Source</em>}</li>
 *   <li>{@link org.rsaml.model.Connection#getTarget <em>Target</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getConnection()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA02_connectedPortTypes RSA03_adjacentLayerCommunication'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA02_connectedPortTypes='(source &lt;&gt; null and target &lt;&gt; null) implies (source.dataType = target.dataType and (source.dataType = DataType::structured implies source.normalizedMessageType() = target.normalizedMessageType()))' RSA03_adjacentLayerCommunication='let from : Layer = if source = null or source.module = null then null else source.module.layer endif, to : Layer = if target = null or target.module = null then null else target.module.layer endif in (from &lt;&gt; null and to &lt;&gt; null) implies (from.level - to.level).abs() &lt;= 1'"
 * @generated
 */
public interface Connection extends EObject {
	/**
	 * Returns the value of the '<em><b>Architecture</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Architecture#getConnections <em>Connections</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The architecture that contains this connection.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Architecture</em>' container reference.
	 * @see #setArchitecture(Architecture)
	 * @see org.rsaml.model.RsamlPackage#getConnection_Architecture()
	 * @see org.rsaml.model.Architecture#getConnections
	 * @model opposite="connections"
	 * @generated
	 */
	Architecture getArchitecture();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Connection#getArchitecture <em>Architecture</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Architecture</em>' container reference.
	 * @see #getArchitecture()
	 * @generated
	 */
	void setArchitecture(Architecture value);

	/**
	 * Returns the value of the '<em><b>Source</b></em>' reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.OutputPort#getOutgoing <em>Outgoing</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The output port the data leaves from.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Source</em>' reference.
	 * @see #setSource(OutputPort)
	 * @see org.rsaml.model.RsamlPackage#getConnection_Source()
	 * @see org.rsaml.model.OutputPort#getOutgoing
	 * @model opposite="outgoing" required="true"
	 * @generated
	 */
	OutputPort getSource();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Connection#getSource <em>Source</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Source</em>' reference.
	 * @see #getSource()
	 * @generated
	 */
	void setSource(OutputPort value);

	/**
	 * Returns the value of the '<em><b>Target</b></em>' reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.EntryPort#getIncoming <em>Incoming</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The entry port the data arrives at.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Target</em>' reference.
	 * @see #setTarget(EntryPort)
	 * @see org.rsaml.model.RsamlPackage#getConnection_Target()
	 * @see org.rsaml.model.EntryPort#getIncoming
	 * @model opposite="incoming" required="true"
	 * @generated
	 */
	EntryPort getTarget();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Connection#getTarget <em>Target</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Target</em>' reference.
	 * @see #getTarget()
	 * @generated
	 */
	void setTarget(EntryPort value);

} // Connection
