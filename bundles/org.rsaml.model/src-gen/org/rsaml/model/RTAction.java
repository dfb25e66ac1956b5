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
 * @model
 * @generated
 */
public interface RTAction extends Action {
} // RTAction
