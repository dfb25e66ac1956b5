/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Processor</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A scheduling domain (e.g. one CPU core) and the modules allocated to it. Every timed release and reaction of an allocated module runs there; the modules no processor names run on a processor of their own, named 'default'. A processor may be on another machine (host), reached through a link with a latency.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Processor#getSchedPolicy <em>Sched Policy</em>}</li>
 *   <li>{@link org.rsaml.model.Processor#getCore <em>Core</em>}</li>
 *   <li>{@link org.rsaml.model.Processor#getModules <em>Modules</em>}</li>
 *   <li>{@link org.rsaml.model.Processor#getHost <em>Host</em>}</li>
 *   <li>{@link org.rsaml.model.Processor#getLinkLatency <em>Link Latency</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getProcessor()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA13_nonNegativeTimes RSA20_representableTimes RSA29_packageNameUsable'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA13_nonNegativeTimes='linkLatency &gt;= 0' RSA20_representableTimes='representable(linkLatency)' RSA29_packageNameUsable='packageProblem() = null'"
 * @generated
 */
public interface Processor extends NamedElement, TimeScaled {
	/**
	 * Returns the value of the '<em><b>Sched Policy</b></em>' attribute.
	 * The literals are from the enumeration {@link org.rsaml.model.SchedulingPolicy}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * How the processor schedules its work. Not set: the fixed priorities the generated runtime assigns (rate and deadline monotonic ranks, FIFO and RR at the base rank), as FIFO, RR, RM and DM also mean. EDF, LLF, SJF and OTHER describe a platform scheduler the generated runtime does not set up.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Sched Policy</em>' attribute.
	 * @see org.rsaml.model.SchedulingPolicy
	 * @see #isSetSchedPolicy()
	 * @see #unsetSchedPolicy()
	 * @see #setSchedPolicy(SchedulingPolicy)
	 * @see org.rsaml.model.RsamlPackage#getProcessor_SchedPolicy()
	 * @model unsettable="true"
	 * @generated
	 */
	SchedulingPolicy getSchedPolicy();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Processor#getSchedPolicy <em>Sched Policy</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Sched Policy</em>' attribute.
	 * @see org.rsaml.model.SchedulingPolicy
	 * @see #isSetSchedPolicy()
	 * @see #unsetSchedPolicy()
	 * @see #getSchedPolicy()
	 * @generated
	 */
	void setSchedPolicy(SchedulingPolicy value);

	/**
	 * Unsets the value of the '{@link org.rsaml.model.Processor#getSchedPolicy <em>Sched Policy</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #isSetSchedPolicy()
	 * @see #getSchedPolicy()
	 * @see #setSchedPolicy(SchedulingPolicy)
	 * @generated
	 */
	void unsetSchedPolicy();

	/**
	 * Returns whether the value of the '{@link org.rsaml.model.Processor#getSchedPolicy <em>Sched Policy</em>}' attribute is set.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return whether the value of the '<em>Sched Policy</em>' attribute is set.
	 * @see #unsetSchedPolicy()
	 * @see #getSchedPolicy()
	 * @see #setSchedPolicy(SchedulingPolicy)
	 * @generated
	 */
	boolean isSetSchedPolicy();

	/**
	 * Returns the value of the '<em><b>Core</b></em>' attribute.
	 * The default value is <code>"-1"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The CPU core (from 0) the processor's threads are pinned to where the platform permits; -1 leaves the choice to the operating system.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Core</em>' attribute.
	 * @see #setCore(int)
	 * @see org.rsaml.model.RsamlPackage#getProcessor_Core()
	 * @model default="-1"
	 * @generated
	 */
	int getCore();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Processor#getCore <em>Core</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Core</em>' attribute.
	 * @see #getCore()
	 * @generated
	 */
	void setCore(int value);

	/**
	 * Returns the value of the '<em><b>Modules</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Module}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The modules allocated to this processor; a module is allocated to at most one processor.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Modules</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getProcessor_Modules()
	 * @model
	 * @generated
	 */
	EList<org.rsaml.model.Module> getModules();

	/**
	 * Returns the value of the '<em><b>Host</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The machine the processor is on (a computer, a board, a micro-controller); processors naming the same host share a machine. Not set: the architecture's main host. Data between modules on different hosts crosses their links (linkLatency).
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Host</em>' attribute.
	 * @see #setHost(String)
	 * @see org.rsaml.model.RsamlPackage#getProcessor_Host()
	 * @model
	 * @generated
	 */
	String getHost();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Processor#getHost <em>Host</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Host</em>' attribute.
	 * @see #getHost()
	 * @generated
	 */
	void setHost(String value);

	/**
	 * Returns the value of the '<em><b>Link Latency</b></em>' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The longest a message takes through this processor's link (bus or network) to or from another host, in the processor's timeUnit; a message between modules on two different hosts takes the link latencies of both processors. 0: not counted.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Link Latency</em>' attribute.
	 * @see #setLinkLatency(double)
	 * @see org.rsaml.model.RsamlPackage#getProcessor_LinkLatency()
	 * @model
	 * @generated
	 */
	double getLinkLatency();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Processor#getLinkLatency <em>Link Latency</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Link Latency</em>' attribute.
	 * @see #getLinkLatency()
	 * @generated
	 */
	void setLinkLatency(double value);

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * When the architecture asks for a ROS 2 package per processor and modules are allocated to this processor: what makes the package name made from its name unusable (no letters or digits to make it from, a name the generator takes itself, or the package name of another processor); null otherwise.
	 * <!-- end-model-doc -->
	 * @model
	 * @generated
	 */
	String packageProblem();

} // Processor
