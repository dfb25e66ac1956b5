/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Latency Requirement</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * An end-to-end timing requirement: data from the source (a sensor or an output port) must reach the target (an actuator or an entry port) within maxLatency, along every path of connections, suppressors and inhibitors between them, or only the paths through the elements named in via.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.LatencyRequirement#getSource <em>Source</em>}</li>
 *   <li>{@link org.rsaml.model.LatencyRequirement#getTarget <em>Target</em>}</li>
 *   <li>{@link org.rsaml.model.LatencyRequirement#getMaxLatency <em>Max Latency</em>}</li>
 *   <li>{@link org.rsaml.model.LatencyRequirement#getKind <em>Kind</em>}</li>
 *   <li>{@link org.rsaml.model.LatencyRequirement#getVia <em>Via</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getLatencyRequirement()
 * @model
 * @generated
 */
public interface LatencyRequirement extends NamedElement, TimeScaled {
	/**
	 * Returns the value of the '<em><b>Source</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Where the data comes from: a sensor or an output port.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Source</em>' reference.
	 * @see #setSource(NamedElement)
	 * @see org.rsaml.model.RsamlPackage#getLatencyRequirement_Source()
	 * @model required="true"
	 * @generated
	 */
	NamedElement getSource();

	/**
	 * Sets the value of the '{@link org.rsaml.model.LatencyRequirement#getSource <em>Source</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Source</em>' reference.
	 * @see #getSource()
	 * @generated
	 */
	void setSource(NamedElement value);

	/**
	 * Returns the value of the '<em><b>Target</b></em>' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Where the data must arrive: an actuator or an entry port.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Target</em>' reference.
	 * @see #setTarget(NamedElement)
	 * @see org.rsaml.model.RsamlPackage#getLatencyRequirement_Target()
	 * @model required="true"
	 * @generated
	 */
	NamedElement getTarget();

	/**
	 * Sets the value of the '{@link org.rsaml.model.LatencyRequirement#getTarget <em>Target</em>}' reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Target</em>' reference.
	 * @see #getTarget()
	 * @generated
	 */
	void setTarget(NamedElement value);

	/**
	 * Returns the value of the '<em><b>Max Latency</b></em>' attribute.
	 * The default value is <code>"0.0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The longest the chosen latency may be, in timeUnit.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Max Latency</em>' attribute.
	 * @see #setMaxLatency(double)
	 * @see org.rsaml.model.RsamlPackage#getLatencyRequirement_MaxLatency()
	 * @model default="0.0"
	 * @generated
	 */
	double getMaxLatency();

	/**
	 * Sets the value of the '{@link org.rsaml.model.LatencyRequirement#getMaxLatency <em>Max Latency</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Max Latency</em>' attribute.
	 * @see #getMaxLatency()
	 * @generated
	 */
	void setMaxLatency(double value);

	/**
	 * Returns the value of the '<em><b>Kind</b></em>' attribute.
	 * The default value is <code>"reactionTime"</code>.
	 * The literals are from the enumeration {@link org.rsaml.model.LatencyKind}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Which latency is bounded: the reaction time (from a change at the source to its first effect at the target) or the data age (how old the source data the target acts on can be).
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Kind</em>' attribute.
	 * @see org.rsaml.model.LatencyKind
	 * @see #setKind(LatencyKind)
	 * @see org.rsaml.model.RsamlPackage#getLatencyRequirement_Kind()
	 * @model default="reactionTime"
	 * @generated
	 */
	LatencyKind getKind();

	/**
	 * Sets the value of the '{@link org.rsaml.model.LatencyRequirement#getKind <em>Kind</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Kind</em>' attribute.
	 * @see org.rsaml.model.LatencyKind
	 * @see #getKind()
	 * @generated
	 */
	void setKind(LatencyKind value);

	/**
	 * Returns the value of the '<em><b>Via</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.NamedElement}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The path the requirement is about: the modules, ports, inhibitors and suppressors it passes through, in this order (others may lie between them). Empty: every path from the source to the target.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Via</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getLatencyRequirement_Via()
	 * @model
	 * @generated
	 */
	EList<NamedElement> getVia();

} // LatencyRequirement
