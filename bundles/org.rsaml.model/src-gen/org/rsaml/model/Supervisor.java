/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Supervisor</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * Controls the execution of plans; it is realised by a module of the architecture.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Supervisor#getArchitecture <em>Architecture</em>}</li>
 *   <li>{@link org.rsaml.model.Supervisor#getPlans <em>Plans</em>}</li>
 *   <li>{@link org.rsaml.model.Supervisor#getRealisedBy <em>Realised By</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getSupervisor()
 * @model
 * @generated
 */
public interface Supervisor extends NamedElement {
	/**
	 * Returns the value of the '<em><b>Architecture</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Architecture#getSupervisors <em>Supervisors</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The architecture that contains this supervisor.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Architecture</em>' container reference.
	 * @see #setArchitecture(Architecture)
	 * @see org.rsaml.model.RsamlPackage#getSupervisor_Architecture()
	 * @see org.rsaml.model.Architecture#getSupervisors
	 * @model opposite="supervisors"
	 * @generated
	 */
	Architecture getArchitecture();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Supervisor#getArchitecture <em>Architecture</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Architecture</em>' container reference.
	 * @see #getArchitecture()
	 * @generated
	 */
	void setArchitecture(Architecture value);

	/**
	 * Returns the value of the '<em><b>Plans</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Plan}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The plans whose execution this supervisor controls.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Plans</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getSupervisor_Plans()
	 * @model
	 * @generated
	 */
	EList<Plan> getPlans();

	/**
	 * Returns the value of the '<em><b>Realised By</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The module that implements this supervisor.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Realised By</em>' reference.
	 * @see #setRealisedBy(org.rsaml.model.Module)
	 * @see org.rsaml.model.RsamlPackage#getSupervisor_RealisedBy()
	 * @model
	 * @generated
	 */
	org.rsaml.model.Module getRealisedBy();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Supervisor#getRealisedBy <em>Realised By</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Realised By</em>' reference.
	 * @see #getRealisedBy()
	 * @generated
	 */
	void setRealisedBy(org.rsaml.model.Module value);

} // Supervisor
