/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Knowledge</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * Data the robot handles, and how it is used: which modules use it.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Knowledge#getDatabase <em>Database</em>}</li>
 *   <li>{@link org.rsaml.model.Knowledge#getDataType <em>Data Type</em>}</li>
 *   <li>{@link org.rsaml.model.Knowledge#getUsedBy <em>Used By</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getKnowledge()
 * @model
 * @generated
 */
public interface Knowledge extends NamedElement {
	/**
	 * Returns the value of the '<em><b>Database</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Database#getKnowledge <em>Knowledge</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The database that stores this knowledge.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Database</em>' container reference.
	 * @see #setDatabase(Database)
	 * @see org.rsaml.model.RsamlPackage#getKnowledge_Database()
	 * @see org.rsaml.model.Database#getKnowledge
	 * @model opposite="knowledge"
	 * @generated
	 */
	Database getDatabase();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Knowledge#getDatabase <em>Database</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Database</em>' container reference.
	 * @see #getDatabase()
	 * @generated
	 */
	void setDatabase(Database value);

	/**
	 * Returns the value of the '<em><b>Data Type</b></em>' attribute.
	 * The default value is <code>"structured"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.DataType}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The type of the knowledge's data.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Data Type</em>' attribute.
	 * @see org.rsaml.model.DataType
	 * @see #setDataType(DataType)
	 * @see org.rsaml.model.RsamlPackage#getKnowledge_DataType()
	 * @model default="structured"
	 * @generated
	 */
	DataType getDataType();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Knowledge#getDataType <em>Data Type</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Data Type</em>' attribute.
	 * @see org.rsaml.model.DataType
	 * @see #getDataType()
	 * @generated
	 */
	void setDataType(DataType value);

	/**
	 * Returns the value of the '<em><b>Used By</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Module}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The modules that read or update this knowledge.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Used By</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getKnowledge_UsedBy()
	 * @model
	 * @generated
	 */
	EList<org.rsaml.model.Module> getUsedBy();

} // Knowledge
