/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model;

import org.eclipse.emf.common.util.EList;

/**
 * <!-- begin-user-doc -->
 * A representation of the model object '<em><b>Layer</b></em>'.
 * <!-- end-user-doc -->
 *
 * <!-- begin-model-doc -->
 * A level in the hierarchy of the architecture (for example decisional, control, functional), holding modules.
 * <!-- end-model-doc -->
 *
 * <p>
 * The following features are supported:
 * </p>
 * <ul>
 *   <li>{@link org.rsaml.model.Layer#getArchitecture <em>Architecture</em>}</li>
 *   <li>{@link org.rsaml.model.Layer#getLevel <em>Level</em>}</li>
 *   <li>{@link org.rsaml.model.Layer#getMaxExecTime <em>Max Exec Time</em>}</li>
 *   <li>{@link org.rsaml.model.Layer#getModules <em>Modules</em>}</li>
 * </ul>
 *
 * @see org.rsaml.model.RsamlPackage#getLayer()
 * @model annotation="http://www.eclipse.org/emf/2002/Ecore constraints='RSA09_uniqueNames RSA13_nonNegativeTimes RSA20_representableTimes RSA29_packageNameUsable'"
 *        annotation="http://www.eclipse.org/emf/2002/Ecore/OCL RSA09_uniqueNames='modules-&gt;isUnique(normalizedName())' RSA13_nonNegativeTimes='maxExecTime &gt;= 0' RSA20_representableTimes='representable(maxExecTime)' RSA29_packageNameUsable='packageProblem() = null'"
 * @generated
 */
public interface Layer extends NamedElement, TimeScaled {
	/**
	 * Returns the value of the '<em><b>Architecture</b></em>' container reference.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Architecture#getLayers <em>Layers</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The architecture that contains this layer.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Architecture</em>' container reference.
	 * @see #setArchitecture(Architecture)
	 * @see org.rsaml.model.RsamlPackage#getLayer_Architecture()
	 * @see org.rsaml.model.Architecture#getLayers
	 * @model opposite="layers"
	 * @generated
	 */
	Architecture getArchitecture();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Layer#getArchitecture <em>Architecture</em>}' container reference.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Architecture</em>' container reference.
	 * @see #getArchitecture()
	 * @generated
	 */
	void setArchitecture(Architecture value);

	/**
	 * Returns the value of the '<em><b>Level</b></em>' attribute.
	 * The default value is <code>"0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The layer's position in the hierarchy: 0 is the lowest layer, each layer above has the next level.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Level</em>' attribute.
	 * @see #setLevel(int)
	 * @see org.rsaml.model.RsamlPackage#getLayer_Level()
	 * @model default="0"
	 * @generated
	 */
	int getLevel();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Layer#getLevel <em>Level</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Level</em>' attribute.
	 * @see #getLevel()
	 * @generated
	 */
	void setLevel(int value);

	/**
	 * Returns the value of the '<em><b>Max Exec Time</b></em>' attribute.
	 * The default value is <code>"0.0"</code>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * Maximum execution time (MaxExecTime) allowed to each module of the layer, in the layer's time unit; 0 means no budget is set.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Max Exec Time</em>' attribute.
	 * @see #setMaxExecTime(double)
	 * @see org.rsaml.model.RsamlPackage#getLayer_MaxExecTime()
	 * @model default="0.0"
	 * @generated
	 */
	double getMaxExecTime();

	/**
	 * Sets the value of the '{@link org.rsaml.model.Layer#getMaxExecTime <em>Max Exec Time</em>}' attribute.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @param value the new value of the '<em>Max Exec Time</em>' attribute.
	 * @see #getMaxExecTime()
	 * @generated
	 */
	void setMaxExecTime(double value);

	/**
	 * Returns the value of the '<em><b>Modules</b></em>' containment reference list.
	 * The list contents are of type {@link org.rsaml.model.Module}.
	 * It is bidirectional and its opposite is '{@link org.rsaml.model.Module#getLayer <em>Layer</em>}'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * The modules that live in this layer.
	 * <!-- end-model-doc -->
	 * @return the value of the '<em>Modules</em>' containment reference list.
	 * @see org.rsaml.model.RsamlPackage#getLayer_Modules()
	 * @see org.rsaml.model.Module#getLayer
	 * @model opposite="layer" containment="true" keys="name"
	 * @generated
	 */
	EList<org.rsaml.model.Module> getModules();

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * <!-- begin-model-doc -->
	 * When the architecture asks for a ROS 2 package per layer and this layer has modules: what makes the package name made from its name unusable (no letters or digits to make it from, a name the generator takes itself, or the package name of another layer); null otherwise.
	 * <!-- end-model-doc -->
	 * @model
	 * @generated
	 */
	String packageProblem();

} // Layer
