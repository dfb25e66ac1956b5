/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;


/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Port</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A communication point of a module, through which it exchanges data of one type.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Port#getModule <em>Module</em>}</li>
 *   <li>{@link org.rsaml.model.Port#getDataType <em>Data Type</em>}</li>
 *   <li>{@link org.rsaml.model.Port#getMessageType <em>Message Type</em>}</li>
 *   <li>{@link org.rsaml.model.Port#getTopic <em>Topic</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getPort()
 * @model abstract="true"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA18_structuredPortNamesMessageType RSA28_topicNameUsable'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA18_structuredPortNamesMessageType='dataType = DataType::structured implies normalizedMessageType() &lt;&gt; null' RSA28_topicNameUsable='topicProblem() = null'"
 * @generated
 */
public interface Port extends NamedElement {
	/**
	 * Returns the value of the '<em><b>Module</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Module#getPorts <em>Ports</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The module that owns this port.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Module</em>' container reference.
	 * @see #setModule(org.rsaml.model.Module)
	 * @see org.rsaml.model.RsamlPackage#getPort_Module()
	 * @see org.rsaml.model.Module#getPorts
	 * @model opposite="ports"
	 * @generated
	 */
	org.rsaml.model.Module getModule();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Port#getModule <em>Module</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Module</em>' container reference.
	 * @see #getModule()
	 * @generated
	 */
	void setModule(org.rsaml.model.Module value);

	/**
	 * Returns the value of the '<em><b>Data Type</b></em>' attribute.
	 * The default value is <code>"numeric"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.DataType}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The type of data the port exchanges. Two connected ports must have the same data type.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Data Type</em>' attribute.
	 * @see org.rsaml.model.DataType
	 * @see #setDataType(DataType)
	 * @see org.rsaml.model.RsamlPackage#getPort_DataType()
	 * @model default="numeric"
	 * @generated
	 */
	DataType getDataType();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Port#getDataType <em>Data Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Data Type</em>' attribute.
	 * @see org.rsaml.model.DataType
	 * @see #getDataType()
	 * @generated
	 */
	void setDataType(DataType value);

	/**
	 * Returns the value of the '<em><b>Message Type</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * For structured data, the name of the message type exchanged (for example geometry_msgs/msg/Twist); two connected structured ports must name the same message type.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Message Type</em>' attribute.
	 * @see #setMessageType(String)
	 * @see org.rsaml.model.RsamlPackage#getPort_MessageType()
	 * @model
	 * @generated
	 */
	String getMessageType();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Port#getMessageType <em>Message Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Message Type</em>' attribute.
	 * @see #getMessageType()
	 * @generated
	 */
	void setMessageType(String value);

	/**
	 * Returns the value of the '<em><b>Topic</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The ROS 2 topic the port publishes or subscribes to (for example scan, cmd_vel or /tf): relative names resolve in the nodes' namespace. Ports connected to each other share one topic, so they name the same one or one of them names it; when none does, the generated packages name it after the publishing module's path.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Topic</em>' attribute.
	 * @see #setTopic(String)
	 * @see org.rsaml.model.RsamlPackage#getPort_Topic()
	 * @model
	 * @generated
	 */
	String getTopic();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Port#getTopic <em>Topic</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Topic</em>' attribute.
	 * @see #getTopic()
	 * @generated
	 */
	void setTopic(String value);

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The message type without surrounding white space; null when it is missing or blank. Rules and generators compare message types this way.
	 * <!-- end-model-doc -->
	 * @model
	 * @generated
	 */
	String normalizedMessageType();

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * What makes the topic this port names unusable as a ROS 2 topic (not a valid name, another name than a port it is connected to, or the name of ports it is not connected to); null when it names none or the name is usable.
	 * <!-- end-model-doc -->
	 * @model
	 * @generated
	 */
	String topicProblem();

} // Port
