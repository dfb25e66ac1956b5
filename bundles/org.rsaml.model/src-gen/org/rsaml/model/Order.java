/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;


/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Order</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * An order sent to the robot, by an operator or another system, to perform a task.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Order#getArchitecture <em>Architecture</em>}</li>
 *   <li>{@link org.rsaml.model.Order#getIssuer <em>Issuer</em>}</li>
 *   <li>{@link org.rsaml.model.Order#getReceiver <em>Receiver</em>}</li>
 *   <li>{@link org.rsaml.model.Order#getRequests <em>Requests</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getOrder()
 * @model
 * @generated
 */
public interface Order extends NamedElement {
	/**
	 * Returns the value of the '<em><b>Architecture</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Architecture#getOrders <em>Orders</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The architecture that contains this order.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Architecture</em>' container reference.
	 * @see #setArchitecture(Architecture)
	 * @see org.rsaml.model.RsamlPackage#getOrder_Architecture()
	 * @see org.rsaml.model.Architecture#getOrders
	 * @model opposite="orders"
	 * @generated
	 */
	Architecture getArchitecture();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Order#getArchitecture <em>Architecture</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Architecture</em>' container reference.
	 * @see #getArchitecture()
	 * @generated
	 */
	void setArchitecture(Architecture value);

	/**
	 * Returns the value of the '<em><b>Issuer</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Who sends the order (for example an operator).
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Issuer</em>' attribute.
	 * @see #setIssuer(String)
	 * @see org.rsaml.model.RsamlPackage#getOrder_Issuer()
	 * @model
	 * @generated
	 */
	String getIssuer();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Order#getIssuer <em>Issuer</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Issuer</em>' attribute.
	 * @see #getIssuer()
	 * @generated
	 */
	void setIssuer(String value);

	/**
	 * Returns the value of the '<em><b>Receiver</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The module that receives the order.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Receiver</em>' reference.
	 * @see #setReceiver(org.rsaml.model.Module)
	 * @see org.rsaml.model.RsamlPackage#getOrder_Receiver()
	 * @model
	 * @generated
	 */
	org.rsaml.model.Module getReceiver();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Order#getReceiver <em>Receiver</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Receiver</em>' reference.
	 * @see #getReceiver()
	 * @generated
	 */
	void setReceiver(org.rsaml.model.Module value);

	/**
	 * Returns the value of the '<em><b>Requests</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The activity the order asks the robot to perform.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Requests</em>' reference.
	 * @see #setRequests(Activity)
	 * @see org.rsaml.model.RsamlPackage#getOrder_Requests()
	 * @model
	 * @generated
	 */
	Activity getRequests();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Order#getRequests <em>Requests</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Requests</em>' reference.
	 * @see #getRequests()
	 * @generated
	 */
	void setRequests(Activity value);

} // Order
