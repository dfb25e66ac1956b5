/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Module</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A robotic software component: it offers functions, communicates through entry and output ports, reads sensors, drives actuators, and may inhibit or suppress the ports of other modules.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Module#getLayer <em>Layer</em>}</li>
 *   <li>{@link org.rsaml.model.Module#getFunctions <em>Functions</em>}</li>
 *   <li>{@link org.rsaml.model.Module#getPorts <em>Ports</em>}</li>
 *   <li>{@link org.rsaml.model.Module#getInhibitors <em>Inhibitors</em>}</li>
 *   <li>{@link org.rsaml.model.Module#getSuppressors <em>Suppressors</em>}</li>
 *   <li>{@link org.rsaml.model.Module#getSensors <em>Sensors</em>}</li>
 *   <li>{@link org.rsaml.model.Module#getActuators <em>Actuators</em>}</li>
 *   <li>{@link org.rsaml.model.Module#getLifecycle <em>Lifecycle</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getModule()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA05_realTimeModuleTiming RSA06_realTimeModuleFunctions RSA08_layerExecutionBudget RSA09_uniqueNames RSA19_activatedModule'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA05_realTimeModuleTiming='type = ElementType::realTime implies (period &gt; 0 and delay &gt; 0)' RSA06_realTimeModuleFunctions='type = ElementType::realTime implies functions-&gt;forAll(f | f.type = ElementType::realTime)' RSA08_layerExecutionBudget='(layer &lt;&gt; null and layer.maxExecTime &gt; 0) implies compareTime(execDuration, layer, layer.maxExecTime) &lt;= 0' RSA09_uniqueNames='ports-&gt;isUnique(normalizedName()) and functions-&gt;isUnique(normalizedName()) and inhibitors-&gt;isUnique(normalizedName()) and suppressors-&gt;isUnique(normalizedName())' RSA19_activatedModule='Set{self}-&gt;closure(m | m.ports-&gt;select(p | p.oclIsKindOf(EntryPort) and not ((m.execType = ExecutionType::periodic and m.period &gt; 0) or m.functions-&gt;exists(f | (f.execType = ExecutionType::periodic and f.period &gt; 0) or f.actions-&gt;exists(a | a.execType = ExecutionType::periodic and a.period &gt; 0))))-&gt;collect(p | p.oclAsType(EntryPort))-&gt;collect(e | e.incoming-&gt;select(c | c.source &lt;&gt; null and c.source.module &lt;&gt; null and c.source.dataType = e.dataType and (e.dataType = DataType::structured implies c.source.normalizedMessageType() = e.normalizedMessageType()))-&gt;collect(c | c.source.module)-&gt;union(e.suppressedBy-&gt;select(s | s.trigger &lt;&gt; null and s.trigger.module &lt;&gt; null and s.trigger.dataType = e.dataType and (e.dataType = DataType::structured implies s.trigger.normalizedMessageType() = e.normalizedMessageType()))-&gt;collect(s | s.trigger.module))))-&gt;including(self)-&gt;exists(m | (m.execType = ExecutionType::periodic and m.period &gt; 0) or m.functions-&gt;exists(f | (f.execType = ExecutionType::periodic and f.period &gt; 0) or f.actions-&gt;exists(a | a.execType = ExecutionType::periodic and a.period &gt; 0)))'"
 * @generated
 */
public interface Module extends RealTimeElement {
	/**
	 * Returns the value of the '<em><b>Layer</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Layer#getModules <em>Modules</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The layer that contains this module.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Layer</em>' container reference.
	 * @see #setLayer(Layer)
	 * @see org.rsaml.model.RsamlPackage#getModule_Layer()
	 * @see org.rsaml.model.Layer#getModules
	 * @model opposite="modules"
	 * @generated
	 */
	Layer getLayer();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Module#getLayer <em>Layer</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Layer</em>' container reference.
	 * @see #getLayer()
	 * @generated
	 */
	void setLayer(Layer value);

	/**
	 * Returns the value of the '<em><b>Functions</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Function}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Function#getModule <em>Module</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The functions that implement the module.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Functions</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getModule_Functions()
	 * @see org.rsaml.model.Function#getModule
	 * @model opposite="module" containment="true" keys="name"
	 * @generated
	 */
	EList<Function> getFunctions();

	/**
	 * Returns the value of the '<em><b>Ports</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Port}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Port#getModule <em>Module</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The module's communication interface: its entry ports and output ports.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Ports</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getModule_Ports()
	 * @see org.rsaml.model.Port#getModule
	 * @model opposite="module" containment="true" keys="name"
	 * @generated
	 */
	EList<Port> getPorts();

	/**
	 * Returns the value of the '<em><b>Inhibitors</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Inhibitor}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Inhibitor#getModule <em>Module</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The inhibitors by which this module blocks outputs of other modules.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Inhibitors</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getModule_Inhibitors()
	 * @see org.rsaml.model.Inhibitor#getModule
	 * @model opposite="module" containment="true" keys="name"
	 * @generated
	 */
	EList<Inhibitor> getInhibitors();

	/**
	 * Returns the value of the '<em><b>Suppressors</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Suppressor}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Suppressor#getModule <em>Module</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The suppressors by which this module replaces inputs of other modules.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Suppressors</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getModule_Suppressors()
	 * @see org.rsaml.model.Suppressor#getModule
	 * @model opposite="module" containment="true" keys="name"
	 * @generated
	 */
	EList<Suppressor> getSuppressors();

	/**
	 * Returns the value of the '<em><b>Sensors</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Sensor}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Sensor#getModules <em>Modules</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The sensors this module reads.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Sensors</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getModule_Sensors()
	 * @see org.rsaml.model.Sensor#getModules
	 * @model opposite="modules"
	 * @generated
	 */
	EList<Sensor> getSensors();

	/**
	 * Returns the value of the '<em><b>Actuators</b></em>' reference list.
	 * The list contents are of type {@link org.rsaml.model.Actuator}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Actuator#getModules <em>Modules</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The actuators this module drives.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Actuators</em>' reference list.
	 * @see org.rsaml.model.RsamlPackage#getModule_Actuators()
	 * @see org.rsaml.model.Actuator#getModules
	 * @model opposite="modules"
	 * @generated
	 */
	EList<Actuator> getActuators();

	/**
	 * Returns the value of the '<em><b>Lifecycle</b></em>' attribute.
	 * The literals are from the enumeration {@link org.rsaml.model.NodeLifecycle}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * This module's choice of a plain or a managed ROS 2 node, when it differs from its architecture's lifecycle; unset, the module follows the architecture.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Lifecycle</em>' attribute.
	 * @see org.rsaml.model.NodeLifecycle
	 * @see #isSetLifecycle()
	 * @see #unsetLifecycle()
	 * @see #setLifecycle(NodeLifecycle)
	 * @see org.rsaml.model.RsamlPackage#getModule_Lifecycle()
	 * @model unsettable="true"
	 * @generated
	 */
	NodeLifecycle getLifecycle();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Module#getLifecycle <em>Lifecycle</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Lifecycle</em>' attribute.
	 * @see org.rsaml.model.NodeLifecycle
	 * @see #isSetLifecycle()
	 * @see #unsetLifecycle()
	 * @see #getLifecycle()
	 * @generated
	 */
	void setLifecycle(NodeLifecycle value);

	/**
	 * Unsets the value of the '{@link org.rsaml.model.Module#getLifecycle <em>Lifecycle</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #isSetLifecycle()
	 * @see #getLifecycle()
	 * @see #setLifecycle(NodeLifecycle)
	 * @generated
	 */
	void unsetLifecycle();

	/**
	 * Returns whether the value of the '{@link org.rsaml.model.Module#getLifecycle <em>Lifecycle</em>}' attribute is set.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @return whether the value of the '<em>Lifecycle</em>' attribute is set.
	 * @see #unsetLifecycle()
	 * @see #getLifecycle()
	 * @see #setLifecycle(NodeLifecycle)
	 * @generated
	 */
	boolean isSetLifecycle();

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The lifecycle this module's node has: its own lifecycle when it sets one, else its architecture's.
	 * <!-- end-model-doc -->
	 * @model
	 * @generated
	 */
	NodeLifecycle effectiveLifecycle();

} // Module
