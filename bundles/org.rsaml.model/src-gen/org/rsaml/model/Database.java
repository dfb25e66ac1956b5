/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Database</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A database or knowledge base of the robot, holding knowledge.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Database#getArchitecture <em>Architecture</em>}</li>
 *   <li>{@link org.rsaml.model.Database#getKnowledge <em>Knowledge</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getDatabase()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA09_uniqueNames'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA09_uniqueNames='knowledge-&gt;isUnique(normalizedName())'"
 * @generated
 */
public interface Database extends NamedElement {
	/**
	 * Returns the value of the '<em><b>Architecture</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Architecture#getDatabases <em>Databases</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The architecture that contains this database.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Architecture</em>' container reference.
	 * @see #setArchitecture(Architecture)
	 * @see org.rsaml.model.RsamlPackage#getDatabase_Architecture()
	 * @see org.rsaml.model.Architecture#getDatabases
	 * @model opposite="databases"
	 * @generated
	 */
	Architecture getArchitecture();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Database#getArchitecture <em>Architecture</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Architecture</em>' container reference.
	 * @see #getArchitecture()
	 * @generated
	 */
	void setArchitecture(Architecture value);

	/**
	 * Returns the value of the '<em><b>Knowledge</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Knowledge}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Knowledge#getDatabase <em>Database</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The knowledge stored in this database.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Knowledge</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getDatabase_Knowledge()
	 * @see org.rsaml.model.Knowledge#getDatabase
	 * @model opposite="database" containment="true" keys="name"
	 * @generated
	 */
	EList<Knowledge> getKnowledge();

} // Database
