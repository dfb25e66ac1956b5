/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;


/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Suppressor</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * Replaces (or removes) the data arriving at an entry port of another module while it is active.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Suppressor#getModule <em>Module</em>}</li>
 *   <li>{@link org.rsaml.model.Suppressor#getTarget <em>Target</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getSuppressor()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA04_suppressLayerBelow RSA16_triggerOfOwnModule'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA04_suppressLayerBelow='let own : Layer = if module = null then null else module.layer endif, other : Layer = if target = null or target.module = null then null else target.module.layer endif in (own &lt;&gt; null and other &lt;&gt; null) implies other.level = own.level - 1' RSA16_triggerOfOwnModule='trigger &lt;&gt; null implies trigger.module = module'"
 * @generated
 */
public interface Suppressor extends SubsumptionLink {
	/**
	 * Returns the value of the '<em><b>Module</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Module#getSuppressors <em>Suppressors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The module that suppresses.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Module</em>' container reference.
	 * @see #setModule(org.rsaml.model.Module)
	 * @see org.rsaml.model.RsamlPackage#getSuppressor_Module()
	 * @see org.rsaml.model.Module#getSuppressors
	 * @model opposite="suppressors"
	 * @generated
	 */
	org.rsaml.model.Module getModule();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Suppressor#getModule <em>Module</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Module</em>' container reference.
	 * @see #getModule()
	 * @generated
	 */
	void setModule(org.rsaml.model.Module value);

	/**
	 * Returns the value of the '<em><b>Target</b></em>' reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.EntryPort#getSuppressedBy <em>Suppressed By</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The entry port whose data is replaced.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Target</em>' reference.
	 * @see #setTarget(EntryPort)
	 * @see org.rsaml.model.RsamlPackage#getSuppressor_Target()
	 * @see org.rsaml.model.EntryPort#getSuppressedBy
	 * @model opposite="suppressedBy" required="true"
	 * @generated
	 */
	EntryPort getTarget();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Suppressor#getTarget <em>Target</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Target</em>' reference.
	 * @see #getTarget()
	 * @generated
	 */
	void setTarget(EntryPort value);

} // Suppressor
