/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;


/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>RT Action</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A real-time action: an action whose type must be real-time and whose timing properties are binding.
 * <!-- end-model-doc -->
 *
 *
 * @see org.rsaml.model.RsamlPackage#getRTAction()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA15_rtActionIsRealTime'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA15_rtActionIsRealTime='type = ElementType::realTime'"
 * @generated
 */
public interface RTAction extends Action {
} // RTAction
