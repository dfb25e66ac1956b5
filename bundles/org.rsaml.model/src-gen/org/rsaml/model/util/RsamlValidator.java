/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.util;

import java.util.Map;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.DiagnosticChain;
import org.eclipse.emf.common.util.ResourceLocator;

import org.eclipse.emf.ecore.EPackage;

import org.eclipse.emf.ecore.util.EObjectValidator;

import org.rsaml.model.Action;
import org.rsaml.model.Activity;
import org.rsaml.model.Actuator;
import org.rsaml.model.Architecture;
import org.rsaml.model.ArchitectureCategory;
import org.rsaml.model.Connection;
import org.rsaml.model.DataType;
import org.rsaml.model.Database;
import org.rsaml.model.Device;
import org.rsaml.model.ElementType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.ExecutionType;
import org.rsaml.model.Function;
import org.rsaml.model.Goal;
import org.rsaml.model.Inhibitor;
import org.rsaml.model.Knowledge;
import org.rsaml.model.LatencyKind;
import org.rsaml.model.LatencyRequirement;
import org.rsaml.model.Layer;
import org.rsaml.model.Mission;
import org.rsaml.model.NamedElement;
import org.rsaml.model.Order;
import org.rsaml.model.OutputPort;
import org.rsaml.model.Plan;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;
import org.rsaml.model.RTAction;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.SchedulingPolicy;
import org.rsaml.model.Sensor;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.Supervisor;
import org.rsaml.model.Suppressor;
import org.rsaml.model.SynchronisationType;
import org.rsaml.model.TimeScaled;
import org.rsaml.model.TimeUnit;

/**
 * <!-- begin-user-doc -->
 * The <b>Validator</b> for the model.
 * <!-- end-user-doc -->
 * @see org.rsaml.model.RsamlPackage
 * @generated
 */
public class RsamlValidator extends EObjectValidator {
	/**
	 * The cached model package
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public static final RsamlValidator INSTANCE = new RsamlValidator();

	/**
	 * A constant for the {@link org.eclipse.emf.common.util.Diagnostic#getSource() source} of diagnostic {@link org.eclipse.emf.common.util.Diagnostic#getCode() codes} from this package.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.eclipse.emf.common.util.Diagnostic#getSource()
	 * @see org.eclipse.emf.common.util.Diagnostic#getCode()
	 * @generated
	 */
	public static final String DIAGNOSTIC_SOURCE = "org.rsaml.model";

	/**
	 * A constant with a fixed name that can be used as the base value for additional hand written constants.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private static final int GENERATED_DIAGNOSTIC_CODE_COUNT = 0;

	/**
	 * A constant with a fixed name that can be used as the base value for additional hand written constants in a derived class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final int DIAGNOSTIC_CODE_COUNT = GENERATED_DIAGNOSTIC_CODE_COUNT;

	/**
	 * Creates an instance of the switch.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public RsamlValidator() {
		super();
	}

	/**
	 * Returns the package of this validator switch.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EPackage getEPackage() {
	  return RsamlPackage.eINSTANCE;
	}

	/**
	 * Calls <code>validateXXX</code> for the corresponding classifier of the model.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected boolean validate(int classifierID, Object value, DiagnosticChain diagnostics, Map<Object, Object> context) {
		switch (classifierID) {
			case RsamlPackage.NAMED_ELEMENT:
				return validateNamedElement((NamedElement)value, diagnostics, context);
			case RsamlPackage.TIME_SCALED:
				return validateTimeScaled((TimeScaled)value, diagnostics, context);
			case RsamlPackage.REAL_TIME_ELEMENT:
				return validateRealTimeElement((RealTimeElement)value, diagnostics, context);
			case RsamlPackage.ARCHITECTURE:
				return validateArchitecture((Architecture)value, diagnostics, context);
			case RsamlPackage.LAYER:
				return validateLayer((Layer)value, diagnostics, context);
			case RsamlPackage.MODULE:
				return validateModule((org.rsaml.model.Module)value, diagnostics, context);
			case RsamlPackage.FUNCTION:
				return validateFunction((Function)value, diagnostics, context);
			case RsamlPackage.ACTION:
				return validateAction((Action)value, diagnostics, context);
			case RsamlPackage.RT_ACTION:
				return validateRTAction((RTAction)value, diagnostics, context);
			case RsamlPackage.PORT:
				return validatePort((Port)value, diagnostics, context);
			case RsamlPackage.ENTRY_PORT:
				return validateEntryPort((EntryPort)value, diagnostics, context);
			case RsamlPackage.OUTPUT_PORT:
				return validateOutputPort((OutputPort)value, diagnostics, context);
			case RsamlPackage.CONNECTION:
				return validateConnection((Connection)value, diagnostics, context);
			case RsamlPackage.SUBSUMPTION_LINK:
				return validateSubsumptionLink((SubsumptionLink)value, diagnostics, context);
			case RsamlPackage.INHIBITOR:
				return validateInhibitor((Inhibitor)value, diagnostics, context);
			case RsamlPackage.SUPPRESSOR:
				return validateSuppressor((Suppressor)value, diagnostics, context);
			case RsamlPackage.DEVICE:
				return validateDevice((Device)value, diagnostics, context);
			case RsamlPackage.SENSOR:
				return validateSensor((Sensor)value, diagnostics, context);
			case RsamlPackage.ACTUATOR:
				return validateActuator((Actuator)value, diagnostics, context);
			case RsamlPackage.MISSION:
				return validateMission((Mission)value, diagnostics, context);
			case RsamlPackage.GOAL:
				return validateGoal((Goal)value, diagnostics, context);
			case RsamlPackage.PLAN:
				return validatePlan((Plan)value, diagnostics, context);
			case RsamlPackage.ACTIVITY:
				return validateActivity((Activity)value, diagnostics, context);
			case RsamlPackage.SUPERVISOR:
				return validateSupervisor((Supervisor)value, diagnostics, context);
			case RsamlPackage.ORDER:
				return validateOrder((Order)value, diagnostics, context);
			case RsamlPackage.DATABASE:
				return validateDatabase((Database)value, diagnostics, context);
			case RsamlPackage.KNOWLEDGE:
				return validateKnowledge((Knowledge)value, diagnostics, context);
			case RsamlPackage.PROCESSOR:
				return validateProcessor((Processor)value, diagnostics, context);
			case RsamlPackage.LATENCY_REQUIREMENT:
				return validateLatencyRequirement((LatencyRequirement)value, diagnostics, context);
			case RsamlPackage.ARCHITECTURE_CATEGORY:
				return validateArchitectureCategory((ArchitectureCategory)value, diagnostics, context);
			case RsamlPackage.ELEMENT_TYPE:
				return validateElementType((ElementType)value, diagnostics, context);
			case RsamlPackage.EXECUTION_TYPE:
				return validateExecutionType((ExecutionType)value, diagnostics, context);
			case RsamlPackage.TIME_UNIT:
				return validateTimeUnit((TimeUnit)value, diagnostics, context);
			case RsamlPackage.SYNCHRONISATION_TYPE:
				return validateSynchronisationType((SynchronisationType)value, diagnostics, context);
			case RsamlPackage.SCHEDULING_POLICY:
				return validateSchedulingPolicy((SchedulingPolicy)value, diagnostics, context);
			case RsamlPackage.DATA_TYPE:
				return validateDataType((DataType)value, diagnostics, context);
			case RsamlPackage.LATENCY_KIND:
				return validateLatencyKind((LatencyKind)value, diagnostics, context);
			default:
				return true;
		}
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateNamedElement(NamedElement namedElement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(namedElement, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(namedElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(namedElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(namedElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(namedElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(namedElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(namedElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(namedElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(namedElement, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(namedElement, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA21_fileNameLength constraint of '<em>Named Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String NAMED_ELEMENT__RSA21_FILE_NAME_LENGTH__EEXPRESSION = "(normalizedName() = null or normalizedName().size() <= 100) and (oclIsKindOf(Port) implies (oclAsType(Port).normalizedMessageType() = null or oclAsType(Port).normalizedMessageType().size() <= 100))";

	/**
	 * Validates the RSA21_fileNameLength constraint of '<em>Named Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateNamedElement_RSA21_fileNameLength(NamedElement namedElement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.NAMED_ELEMENT,
				 namedElement,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA21_fileNameLength",
				 NAMED_ELEMENT__RSA21_FILE_NAME_LENGTH__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateTimeScaled(TimeScaled timeScaled, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return validate_EveryDefaultConstraint(timeScaled, diagnostics, context);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateRealTimeElement(RealTimeElement realTimeElement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(realTimeElement, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA10_executionWithinPeriod(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA11_deadlineWithinPeriod(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA12_periodicHasPeriod(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA13_nonNegativeTimes(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA17_executionWithinDeadline(realTimeElement, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA20_representableTimes(realTimeElement, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA10_executionWithinPeriod constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String REAL_TIME_ELEMENT__RSA10_EXECUTION_WITHIN_PERIOD__EEXPRESSION = "(execType = ExecutionType::periodic and period > 0) implies execDuration <= period";

	/**
	 * Validates the RSA10_executionWithinPeriod constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateRealTimeElement_RSA10_executionWithinPeriod(RealTimeElement realTimeElement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.REAL_TIME_ELEMENT,
				 realTimeElement,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA10_executionWithinPeriod",
				 REAL_TIME_ELEMENT__RSA10_EXECUTION_WITHIN_PERIOD__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA11_deadlineWithinPeriod constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String REAL_TIME_ELEMENT__RSA11_DEADLINE_WITHIN_PERIOD__EEXPRESSION = "(execType = ExecutionType::periodic and period > 0 and delay > 0) implies delay <= period";

	/**
	 * Validates the RSA11_deadlineWithinPeriod constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateRealTimeElement_RSA11_deadlineWithinPeriod(RealTimeElement realTimeElement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.REAL_TIME_ELEMENT,
				 realTimeElement,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA11_deadlineWithinPeriod",
				 REAL_TIME_ELEMENT__RSA11_DEADLINE_WITHIN_PERIOD__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA12_periodicHasPeriod constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String REAL_TIME_ELEMENT__RSA12_PERIODIC_HAS_PERIOD__EEXPRESSION = "execType = ExecutionType::periodic implies period > 0";

	/**
	 * Validates the RSA12_periodicHasPeriod constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateRealTimeElement_RSA12_periodicHasPeriod(RealTimeElement realTimeElement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.REAL_TIME_ELEMENT,
				 realTimeElement,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA12_periodicHasPeriod",
				 REAL_TIME_ELEMENT__RSA12_PERIODIC_HAS_PERIOD__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA13_nonNegativeTimes constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String REAL_TIME_ELEMENT__RSA13_NON_NEGATIVE_TIMES__EEXPRESSION = "period >= 0 and delay >= 0 and execDuration >= 0";

	/**
	 * Validates the RSA13_nonNegativeTimes constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateRealTimeElement_RSA13_nonNegativeTimes(RealTimeElement realTimeElement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.REAL_TIME_ELEMENT,
				 realTimeElement,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA13_nonNegativeTimes",
				 REAL_TIME_ELEMENT__RSA13_NON_NEGATIVE_TIMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA17_executionWithinDeadline constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String REAL_TIME_ELEMENT__RSA17_EXECUTION_WITHIN_DEADLINE__EEXPRESSION = "(type = ElementType::realTime and delay > 0) implies execDuration <= delay";

	/**
	 * Validates the RSA17_executionWithinDeadline constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateRealTimeElement_RSA17_executionWithinDeadline(RealTimeElement realTimeElement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.REAL_TIME_ELEMENT,
				 realTimeElement,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA17_executionWithinDeadline",
				 REAL_TIME_ELEMENT__RSA17_EXECUTION_WITHIN_DEADLINE__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA20_representableTimes constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String REAL_TIME_ELEMENT__RSA20_REPRESENTABLE_TIMES__EEXPRESSION = "representablePeriod(period) and representable(delay) and representable(execDuration)";

	/**
	 * Validates the RSA20_representableTimes constraint of '<em>Real Time Element</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateRealTimeElement_RSA20_representableTimes(RealTimeElement realTimeElement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.REAL_TIME_ELEMENT,
				 realTimeElement,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA20_representableTimes",
				 REAL_TIME_ELEMENT__RSA20_REPRESENTABLE_TIMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateArchitecture(Architecture architecture, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(architecture, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validateArchitecture_RSA01_declaredLayerCount(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validateArchitecture_RSA09_uniqueNames(architecture, diagnostics, context);
		if (result || diagnostics != null) result &= validateArchitecture_RSA14_layerLevels(architecture, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA01_declaredLayerCount constraint of '<em>Architecture</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String ARCHITECTURE__RSA01_DECLARED_LAYER_COUNT__EEXPRESSION = "declaredLayers = layers->size()";

	/**
	 * Validates the RSA01_declaredLayerCount constraint of '<em>Architecture</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateArchitecture_RSA01_declaredLayerCount(Architecture architecture, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.ARCHITECTURE,
				 architecture,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA01_declaredLayerCount",
				 ARCHITECTURE__RSA01_DECLARED_LAYER_COUNT__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA09_uniqueNames constraint of '<em>Architecture</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String ARCHITECTURE__RSA09_UNIQUE_NAMES__EEXPRESSION = "layers->isUnique(normalizedName()) and sensors->isUnique(normalizedName()) and actuators->isUnique(normalizedName()) and missions->isUnique(normalizedName()) and supervisors->isUnique(normalizedName()) and orders->isUnique(normalizedName()) and databases->isUnique(normalizedName())";

	/**
	 * Validates the RSA09_uniqueNames constraint of '<em>Architecture</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateArchitecture_RSA09_uniqueNames(Architecture architecture, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.ARCHITECTURE,
				 architecture,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA09_uniqueNames",
				 ARCHITECTURE__RSA09_UNIQUE_NAMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA14_layerLevels constraint of '<em>Architecture</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String ARCHITECTURE__RSA14_LAYER_LEVELS__EEXPRESSION = "layers->isUnique(level) and layers->forAll(l | l.level >= 0 and l.level < layers->size())";

	/**
	 * Validates the RSA14_layerLevels constraint of '<em>Architecture</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateArchitecture_RSA14_layerLevels(Architecture architecture, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.ARCHITECTURE,
				 architecture,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA14_layerLevels",
				 ARCHITECTURE__RSA14_LAYER_LEVELS__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateLayer(Layer layer, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(layer, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validateLayer_RSA09_uniqueNames(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validateLayer_RSA13_nonNegativeTimes(layer, diagnostics, context);
		if (result || diagnostics != null) result &= validateLayer_RSA20_representableTimes(layer, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA09_uniqueNames constraint of '<em>Layer</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String LAYER__RSA09_UNIQUE_NAMES__EEXPRESSION = "modules->isUnique(normalizedName())";

	/**
	 * Validates the RSA09_uniqueNames constraint of '<em>Layer</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateLayer_RSA09_uniqueNames(Layer layer, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.LAYER,
				 layer,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA09_uniqueNames",
				 LAYER__RSA09_UNIQUE_NAMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA13_nonNegativeTimes constraint of '<em>Layer</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String LAYER__RSA13_NON_NEGATIVE_TIMES__EEXPRESSION = "maxExecTime >= 0";

	/**
	 * Validates the RSA13_nonNegativeTimes constraint of '<em>Layer</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateLayer_RSA13_nonNegativeTimes(Layer layer, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.LAYER,
				 layer,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA13_nonNegativeTimes",
				 LAYER__RSA13_NON_NEGATIVE_TIMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA20_representableTimes constraint of '<em>Layer</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String LAYER__RSA20_REPRESENTABLE_TIMES__EEXPRESSION = "representable(maxExecTime)";

	/**
	 * Validates the RSA20_representableTimes constraint of '<em>Layer</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateLayer_RSA20_representableTimes(Layer layer, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.LAYER,
				 layer,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA20_representableTimes",
				 LAYER__RSA20_REPRESENTABLE_TIMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateModule(org.rsaml.model.Module module, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(module, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(module, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(module, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(module, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(module, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(module, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(module, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(module, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA10_executionWithinPeriod(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA11_deadlineWithinPeriod(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA12_periodicHasPeriod(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA13_nonNegativeTimes(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA17_executionWithinDeadline(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA20_representableTimes(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateModule_RSA05_realTimeModuleTiming(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateModule_RSA06_realTimeModuleFunctions(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateModule_RSA08_layerExecutionBudget(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateModule_RSA09_uniqueNames(module, diagnostics, context);
		if (result || diagnostics != null) result &= validateModule_RSA19_activatedModule(module, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA05_realTimeModuleTiming constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String MODULE__RSA05_REAL_TIME_MODULE_TIMING__EEXPRESSION = "type = ElementType::realTime implies (period > 0 and delay > 0)";

	/**
	 * Validates the RSA05_realTimeModuleTiming constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateModule_RSA05_realTimeModuleTiming(org.rsaml.model.Module module, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.MODULE,
				 module,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA05_realTimeModuleTiming",
				 MODULE__RSA05_REAL_TIME_MODULE_TIMING__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA06_realTimeModuleFunctions constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String MODULE__RSA06_REAL_TIME_MODULE_FUNCTIONS__EEXPRESSION = "type = ElementType::realTime implies functions->forAll(f | f.type = ElementType::realTime)";

	/**
	 * Validates the RSA06_realTimeModuleFunctions constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateModule_RSA06_realTimeModuleFunctions(org.rsaml.model.Module module, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.MODULE,
				 module,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA06_realTimeModuleFunctions",
				 MODULE__RSA06_REAL_TIME_MODULE_FUNCTIONS__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA08_layerExecutionBudget constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String MODULE__RSA08_LAYER_EXECUTION_BUDGET__EEXPRESSION = "(layer <> null and layer.maxExecTime > 0) implies compareTime(execDuration, layer, layer.maxExecTime) <= 0";

	/**
	 * Validates the RSA08_layerExecutionBudget constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateModule_RSA08_layerExecutionBudget(org.rsaml.model.Module module, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.MODULE,
				 module,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA08_layerExecutionBudget",
				 MODULE__RSA08_LAYER_EXECUTION_BUDGET__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA09_uniqueNames constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String MODULE__RSA09_UNIQUE_NAMES__EEXPRESSION = "ports->isUnique(normalizedName()) and functions->isUnique(normalizedName()) and inhibitors->isUnique(normalizedName()) and suppressors->isUnique(normalizedName())";

	/**
	 * Validates the RSA09_uniqueNames constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateModule_RSA09_uniqueNames(org.rsaml.model.Module module, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.MODULE,
				 module,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA09_uniqueNames",
				 MODULE__RSA09_UNIQUE_NAMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA19_activatedModule constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String MODULE__RSA19_ACTIVATED_MODULE__EEXPRESSION = "Set{self}->closure(m | m.ports->select(p | p.oclIsKindOf(EntryPort) and not ((m.execType = ExecutionType::periodic and m.period > 0) or m.functions->exists(f | (f.execType = ExecutionType::periodic and f.period > 0) or f.actions->exists(a | a.execType = ExecutionType::periodic and a.period > 0))))->collect(p | p.oclAsType(EntryPort))->collect(e | e.incoming->select(c | c.source <> null and c.source.module <> null and c.source.dataType = e.dataType and (e.dataType = DataType::structured implies c.source.normalizedMessageType() = e.normalizedMessageType()))->collect(c | c.source.module)->union(e.suppressedBy->select(s | s.trigger <> null and s.trigger.module <> null and s.trigger.dataType = e.dataType and (e.dataType = DataType::structured implies s.trigger.normalizedMessageType() = e.normalizedMessageType()))->collect(s | s.trigger.module))))->including(self)->exists(m | (m.execType = ExecutionType::periodic and m.period > 0) or m.functions->exists(f | (f.execType = ExecutionType::periodic and f.period > 0) or f.actions->exists(a | a.execType = ExecutionType::periodic and a.period > 0)))";

	/**
	 * Validates the RSA19_activatedModule constraint of '<em>Module</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateModule_RSA19_activatedModule(org.rsaml.model.Module module, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.MODULE,
				 module,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA19_activatedModule",
				 MODULE__RSA19_ACTIVATED_MODULE__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateFunction(Function function, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(function, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(function, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(function, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(function, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(function, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(function, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(function, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(function, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA10_executionWithinPeriod(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA11_deadlineWithinPeriod(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA12_periodicHasPeriod(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA13_nonNegativeTimes(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA17_executionWithinDeadline(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA20_representableTimes(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateFunction_RSA07_realTimeFunctionActions(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateFunction_RSA09_uniqueNames(function, diagnostics, context);
		if (result || diagnostics != null) result &= validateFunction_RSA27_functionWithinBudget(function, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA07_realTimeFunctionActions constraint of '<em>Function</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String FUNCTION__RSA07_REAL_TIME_FUNCTION_ACTIONS__EEXPRESSION = "type = ElementType::realTime implies actions->forAll(a | a.type = ElementType::realTime)";

	/**
	 * Validates the RSA07_realTimeFunctionActions constraint of '<em>Function</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateFunction_RSA07_realTimeFunctionActions(Function function, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.FUNCTION,
				 function,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA07_realTimeFunctionActions",
				 FUNCTION__RSA07_REAL_TIME_FUNCTION_ACTIONS__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA09_uniqueNames constraint of '<em>Function</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String FUNCTION__RSA09_UNIQUE_NAMES__EEXPRESSION = "actions->isUnique(normalizedName())";

	/**
	 * Validates the RSA09_uniqueNames constraint of '<em>Function</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateFunction_RSA09_uniqueNames(Function function, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.FUNCTION,
				 function,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA09_uniqueNames",
				 FUNCTION__RSA09_UNIQUE_NAMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA27_functionWithinBudget constraint of '<em>Function</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String FUNCTION__RSA27_FUNCTION_WITHIN_BUDGET__EEXPRESSION = "(module <> null and module.execDuration > 0 implies compareTime(execDuration, module, module.execDuration) <= 0) and ((module <> null and module.layer <> null and module.layer.maxExecTime > 0) implies compareTime(execDuration, module.layer, module.layer.maxExecTime) <= 0)";

	/**
	 * Validates the RSA27_functionWithinBudget constraint of '<em>Function</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateFunction_RSA27_functionWithinBudget(Function function, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.FUNCTION,
				 function,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA27_functionWithinBudget",
				 FUNCTION__RSA27_FUNCTION_WITHIN_BUDGET__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateAction(Action action, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(action, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(action, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(action, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(action, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(action, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(action, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(action, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(action, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(action, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(action, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA10_executionWithinPeriod(action, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA11_deadlineWithinPeriod(action, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA12_periodicHasPeriod(action, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA13_nonNegativeTimes(action, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA17_executionWithinDeadline(action, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA20_representableTimes(action, diagnostics, context);
		if (result || diagnostics != null) result &= validateAction_RSA27_actionWithinBudget(action, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA27_actionWithinBudget constraint of '<em>Action</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String ACTION__RSA27_ACTION_WITHIN_BUDGET__EEXPRESSION = "(function <> null and function.execDuration > 0 implies compareTime(execDuration, function, function.execDuration) <= 0) and ((function <> null and function.module <> null and function.module.execDuration > 0) implies compareTime(execDuration, function.module, function.module.execDuration) <= 0) and ((function <> null and function.module <> null and function.module.layer <> null and function.module.layer.maxExecTime > 0) implies compareTime(execDuration, function.module.layer, function.module.layer.maxExecTime) <= 0)";

	/**
	 * Validates the RSA27_actionWithinBudget constraint of '<em>Action</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateAction_RSA27_actionWithinBudget(Action action, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.ACTION,
				 action,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA27_actionWithinBudget",
				 ACTION__RSA27_ACTION_WITHIN_BUDGET__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateRTAction(RTAction rtAction, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(rtAction, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA10_executionWithinPeriod(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA11_deadlineWithinPeriod(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA12_periodicHasPeriod(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA13_nonNegativeTimes(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA17_executionWithinDeadline(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA20_representableTimes(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validateAction_RSA27_actionWithinBudget(rtAction, diagnostics, context);
		if (result || diagnostics != null) result &= validateRTAction_RSA15_rtActionIsRealTime(rtAction, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA15_rtActionIsRealTime constraint of '<em>RT Action</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String RT_ACTION__RSA15_RT_ACTION_IS_REAL_TIME__EEXPRESSION = "type = ElementType::realTime";

	/**
	 * Validates the RSA15_rtActionIsRealTime constraint of '<em>RT Action</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateRTAction_RSA15_rtActionIsRealTime(RTAction rtAction, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.RT_ACTION,
				 rtAction,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA15_rtActionIsRealTime",
				 RT_ACTION__RSA15_RT_ACTION_IS_REAL_TIME__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validatePort(Port port, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(port, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(port, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(port, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(port, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(port, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(port, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(port, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(port, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(port, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(port, diagnostics, context);
		if (result || diagnostics != null) result &= validatePort_RSA18_structuredPortNamesMessageType(port, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA18_structuredPortNamesMessageType constraint of '<em>Port</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String PORT__RSA18_STRUCTURED_PORT_NAMES_MESSAGE_TYPE__EEXPRESSION = "dataType = DataType::structured implies normalizedMessageType() <> null";

	/**
	 * Validates the RSA18_structuredPortNamesMessageType constraint of '<em>Port</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validatePort_RSA18_structuredPortNamesMessageType(Port port, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.PORT,
				 port,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA18_structuredPortNamesMessageType",
				 PORT__RSA18_STRUCTURED_PORT_NAMES_MESSAGE_TYPE__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateEntryPort(EntryPort entryPort, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(entryPort, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(entryPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(entryPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(entryPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(entryPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(entryPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(entryPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(entryPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(entryPort, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(entryPort, diagnostics, context);
		if (result || diagnostics != null) result &= validatePort_RSA18_structuredPortNamesMessageType(entryPort, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateOutputPort(OutputPort outputPort, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(outputPort, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(outputPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(outputPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(outputPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(outputPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(outputPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(outputPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(outputPort, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(outputPort, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(outputPort, diagnostics, context);
		if (result || diagnostics != null) result &= validatePort_RSA18_structuredPortNamesMessageType(outputPort, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateConnection(Connection connection, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(connection, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(connection, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(connection, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(connection, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(connection, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(connection, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(connection, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(connection, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(connection, diagnostics, context);
		if (result || diagnostics != null) result &= validateConnection_RSA02_connectedPortTypes(connection, diagnostics, context);
		if (result || diagnostics != null) result &= validateConnection_RSA03_adjacentLayerCommunication(connection, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA02_connectedPortTypes constraint of '<em>Connection</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String CONNECTION__RSA02_CONNECTED_PORT_TYPES__EEXPRESSION = "(source <> null and target <> null) implies (source.dataType = target.dataType and (source.dataType = DataType::structured implies source.normalizedMessageType() = target.normalizedMessageType()))";

	/**
	 * Validates the RSA02_connectedPortTypes constraint of '<em>Connection</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateConnection_RSA02_connectedPortTypes(Connection connection, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.CONNECTION,
				 connection,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA02_connectedPortTypes",
				 CONNECTION__RSA02_CONNECTED_PORT_TYPES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA03_adjacentLayerCommunication constraint of '<em>Connection</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String CONNECTION__RSA03_ADJACENT_LAYER_COMMUNICATION__EEXPRESSION = "let from : Layer = if source = null or source.module = null then null else source.module.layer endif, to : Layer = if target = null or target.module = null then null else target.module.layer endif in (from <> null and to <> null) implies (from.level - to.level).abs() <= 1";

	/**
	 * Validates the RSA03_adjacentLayerCommunication constraint of '<em>Connection</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateConnection_RSA03_adjacentLayerCommunication(Connection connection, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.CONNECTION,
				 connection,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA03_adjacentLayerCommunication",
				 CONNECTION__RSA03_ADJACENT_LAYER_COMMUNICATION__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSubsumptionLink(SubsumptionLink subsumptionLink, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(subsumptionLink, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validateSubsumptionLink_RSA13_nonNegativeTimes(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validateSubsumptionLink_RSA20_representableTimes(subsumptionLink, diagnostics, context);
		if (result || diagnostics != null) result &= validateSubsumptionLink_RSA26_durationBelowTriggerPeriod(subsumptionLink, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA13_nonNegativeTimes constraint of '<em>Subsumption Link</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String SUBSUMPTION_LINK__RSA13_NON_NEGATIVE_TIMES__EEXPRESSION = "duration >= 0";

	/**
	 * Validates the RSA13_nonNegativeTimes constraint of '<em>Subsumption Link</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSubsumptionLink_RSA13_nonNegativeTimes(SubsumptionLink subsumptionLink, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.SUBSUMPTION_LINK,
				 subsumptionLink,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA13_nonNegativeTimes",
				 SUBSUMPTION_LINK__RSA13_NON_NEGATIVE_TIMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA20_representableTimes constraint of '<em>Subsumption Link</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String SUBSUMPTION_LINK__RSA20_REPRESENTABLE_TIMES__EEXPRESSION = "representable(duration)";

	/**
	 * Validates the RSA20_representableTimes constraint of '<em>Subsumption Link</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSubsumptionLink_RSA20_representableTimes(SubsumptionLink subsumptionLink, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.SUBSUMPTION_LINK,
				 subsumptionLink,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA20_representableTimes",
				 SUBSUMPTION_LINK__RSA20_REPRESENTABLE_TIMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA26_durationBelowTriggerPeriod constraint of '<em>Subsumption Link</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String SUBSUMPTION_LINK__RSA26_DURATION_BELOW_TRIGGER_PERIOD__EEXPRESSION = "(trigger <> null and trigger.module <> null and duration > 0) implies (((trigger.module.execType = ExecutionType::periodic and trigger.module.period > 0) and (trigger.module.functions->exists(f | not (f.execType = ExecutionType::periodic and f.period > 0)) or not trigger.module.functions->exists(f | (f.execType = ExecutionType::periodic and f.period > 0) or f.actions->exists(a | (a.execType = ExecutionType::periodic and a.period > 0)))) implies trigger.module.compareTime(trigger.module.period, self, duration) > 0) and trigger.module.functions->forAll(f | (f.execType = ExecutionType::periodic and f.period > 0) implies f.compareTime(f.period, self, duration) > 0) and trigger.module.functions->forAll(f | f.actions->forAll(a | (a.execType = ExecutionType::periodic and a.period > 0) implies a.compareTime(a.period, self, duration) > 0)))";

	/**
	 * Validates the RSA26_durationBelowTriggerPeriod constraint of '<em>Subsumption Link</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSubsumptionLink_RSA26_durationBelowTriggerPeriod(SubsumptionLink subsumptionLink, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.SUBSUMPTION_LINK,
				 subsumptionLink,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA26_durationBelowTriggerPeriod",
				 SUBSUMPTION_LINK__RSA26_DURATION_BELOW_TRIGGER_PERIOD__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateInhibitor(Inhibitor inhibitor, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(inhibitor, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validateSubsumptionLink_RSA13_nonNegativeTimes(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validateSubsumptionLink_RSA20_representableTimes(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validateSubsumptionLink_RSA26_durationBelowTriggerPeriod(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validateInhibitor_RSA04_inhibitLayerBelow(inhibitor, diagnostics, context);
		if (result || diagnostics != null) result &= validateInhibitor_RSA16_triggerOfOwnModule(inhibitor, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA04_inhibitLayerBelow constraint of '<em>Inhibitor</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String INHIBITOR__RSA04_INHIBIT_LAYER_BELOW__EEXPRESSION = "let own : Layer = if module = null then null else module.layer endif, other : Layer = if target = null or target.module = null then null else target.module.layer endif in (own <> null and other <> null) implies other.level = own.level - 1";

	/**
	 * Validates the RSA04_inhibitLayerBelow constraint of '<em>Inhibitor</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateInhibitor_RSA04_inhibitLayerBelow(Inhibitor inhibitor, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.INHIBITOR,
				 inhibitor,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA04_inhibitLayerBelow",
				 INHIBITOR__RSA04_INHIBIT_LAYER_BELOW__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA16_triggerOfOwnModule constraint of '<em>Inhibitor</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String INHIBITOR__RSA16_TRIGGER_OF_OWN_MODULE__EEXPRESSION = "trigger <> null implies trigger.module = module";

	/**
	 * Validates the RSA16_triggerOfOwnModule constraint of '<em>Inhibitor</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateInhibitor_RSA16_triggerOfOwnModule(Inhibitor inhibitor, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.INHIBITOR,
				 inhibitor,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA16_triggerOfOwnModule",
				 INHIBITOR__RSA16_TRIGGER_OF_OWN_MODULE__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSuppressor(Suppressor suppressor, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(suppressor, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validateSubsumptionLink_RSA13_nonNegativeTimes(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validateSubsumptionLink_RSA20_representableTimes(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validateSubsumptionLink_RSA26_durationBelowTriggerPeriod(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validateSuppressor_RSA04_suppressLayerBelow(suppressor, diagnostics, context);
		if (result || diagnostics != null) result &= validateSuppressor_RSA16_triggerOfOwnModule(suppressor, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA04_suppressLayerBelow constraint of '<em>Suppressor</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String SUPPRESSOR__RSA04_SUPPRESS_LAYER_BELOW__EEXPRESSION = "let own : Layer = if module = null then null else module.layer endif, other : Layer = if target = null or target.module = null then null else target.module.layer endif in (own <> null and other <> null) implies other.level = own.level - 1";

	/**
	 * Validates the RSA04_suppressLayerBelow constraint of '<em>Suppressor</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSuppressor_RSA04_suppressLayerBelow(Suppressor suppressor, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.SUPPRESSOR,
				 suppressor,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA04_suppressLayerBelow",
				 SUPPRESSOR__RSA04_SUPPRESS_LAYER_BELOW__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA16_triggerOfOwnModule constraint of '<em>Suppressor</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String SUPPRESSOR__RSA16_TRIGGER_OF_OWN_MODULE__EEXPRESSION = "trigger <> null implies trigger.module = module";

	/**
	 * Validates the RSA16_triggerOfOwnModule constraint of '<em>Suppressor</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSuppressor_RSA16_triggerOfOwnModule(Suppressor suppressor, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.SUPPRESSOR,
				 suppressor,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA16_triggerOfOwnModule",
				 SUPPRESSOR__RSA16_TRIGGER_OF_OWN_MODULE__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateDevice(Device device, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(device, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(device, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(device, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(device, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(device, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(device, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(device, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(device, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(device, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(device, diagnostics, context);
		if (result || diagnostics != null) result &= validateDevice_RSA13_nonNegativeTimes(device, diagnostics, context);
		if (result || diagnostics != null) result &= validateDevice_RSA20_representableTimes(device, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA13_nonNegativeTimes constraint of '<em>Device</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String DEVICE__RSA13_NON_NEGATIVE_TIMES__EEXPRESSION = "period >= 0";

	/**
	 * Validates the RSA13_nonNegativeTimes constraint of '<em>Device</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateDevice_RSA13_nonNegativeTimes(Device device, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.DEVICE,
				 device,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA13_nonNegativeTimes",
				 DEVICE__RSA13_NON_NEGATIVE_TIMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * The cached validation expression for the RSA20_representableTimes constraint of '<em>Device</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String DEVICE__RSA20_REPRESENTABLE_TIMES__EEXPRESSION = "representablePeriod(period)";

	/**
	 * Validates the RSA20_representableTimes constraint of '<em>Device</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateDevice_RSA20_representableTimes(Device device, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.DEVICE,
				 device,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA20_representableTimes",
				 DEVICE__RSA20_REPRESENTABLE_TIMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSensor(Sensor sensor, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(sensor, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validateDevice_RSA13_nonNegativeTimes(sensor, diagnostics, context);
		if (result || diagnostics != null) result &= validateDevice_RSA20_representableTimes(sensor, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateActuator(Actuator actuator, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(actuator, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validateDevice_RSA13_nonNegativeTimes(actuator, diagnostics, context);
		if (result || diagnostics != null) result &= validateDevice_RSA20_representableTimes(actuator, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateMission(Mission mission, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(mission, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(mission, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(mission, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(mission, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(mission, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(mission, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(mission, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(mission, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(mission, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(mission, diagnostics, context);
		if (result || diagnostics != null) result &= validateMission_RSA09_uniqueNames(mission, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA09_uniqueNames constraint of '<em>Mission</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String MISSION__RSA09_UNIQUE_NAMES__EEXPRESSION = "goals->isUnique(normalizedName()) and plans->isUnique(normalizedName())";

	/**
	 * Validates the RSA09_uniqueNames constraint of '<em>Mission</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateMission_RSA09_uniqueNames(Mission mission, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.MISSION,
				 mission,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA09_uniqueNames",
				 MISSION__RSA09_UNIQUE_NAMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateGoal(Goal goal, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(goal, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(goal, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(goal, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(goal, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(goal, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(goal, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(goal, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(goal, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(goal, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(goal, diagnostics, context);
		if (result || diagnostics != null) result &= validateGoal_RSA09_uniqueNames(goal, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA09_uniqueNames constraint of '<em>Goal</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String GOAL__RSA09_UNIQUE_NAMES__EEXPRESSION = "subGoals->isUnique(normalizedName())";

	/**
	 * Validates the RSA09_uniqueNames constraint of '<em>Goal</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateGoal_RSA09_uniqueNames(Goal goal, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.GOAL,
				 goal,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA09_uniqueNames",
				 GOAL__RSA09_UNIQUE_NAMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validatePlan(Plan plan, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(plan, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(plan, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(plan, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(plan, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(plan, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(plan, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(plan, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(plan, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(plan, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(plan, diagnostics, context);
		if (result || diagnostics != null) result &= validatePlan_RSA09_uniqueNames(plan, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA09_uniqueNames constraint of '<em>Plan</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String PLAN__RSA09_UNIQUE_NAMES__EEXPRESSION = "activities->isUnique(normalizedName())";

	/**
	 * Validates the RSA09_uniqueNames constraint of '<em>Plan</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validatePlan_RSA09_uniqueNames(Plan plan, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.PLAN,
				 plan,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA09_uniqueNames",
				 PLAN__RSA09_UNIQUE_NAMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateActivity(Activity activity, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(activity, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA10_executionWithinPeriod(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA11_deadlineWithinPeriod(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA12_periodicHasPeriod(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA13_nonNegativeTimes(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA17_executionWithinDeadline(activity, diagnostics, context);
		if (result || diagnostics != null) result &= validateRealTimeElement_RSA20_representableTimes(activity, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSupervisor(Supervisor supervisor, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(supervisor, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(supervisor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(supervisor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(supervisor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(supervisor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(supervisor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(supervisor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(supervisor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(supervisor, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(supervisor, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateOrder(Order order, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(order, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(order, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(order, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(order, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(order, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(order, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(order, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(order, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(order, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(order, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateDatabase(Database database, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(database, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(database, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(database, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(database, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(database, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(database, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(database, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(database, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(database, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(database, diagnostics, context);
		if (result || diagnostics != null) result &= validateDatabase_RSA09_uniqueNames(database, diagnostics, context);
		return result;
	}

	/**
	 * The cached validation expression for the RSA09_uniqueNames constraint of '<em>Database</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected static final String DATABASE__RSA09_UNIQUE_NAMES__EEXPRESSION = "knowledge->isUnique(normalizedName())";

	/**
	 * Validates the RSA09_uniqueNames constraint of '<em>Database</em>'.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateDatabase_RSA09_uniqueNames(Database database, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return
			validate
				(RsamlPackage.Literals.DATABASE,
				 database,
				 diagnostics,
				 context,
				 "http://www.eclipse.org/emf/2002/Ecore/OCL",
				 "RSA09_uniqueNames",
				 DATABASE__RSA09_UNIQUE_NAMES__EEXPRESSION,
				 Diagnostic.ERROR,
				 DIAGNOSTIC_SOURCE,
				 0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateKnowledge(Knowledge knowledge, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(knowledge, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(knowledge, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(knowledge, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(knowledge, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(knowledge, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(knowledge, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(knowledge, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(knowledge, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(knowledge, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(knowledge, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateProcessor(Processor processor, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(processor, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(processor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(processor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(processor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(processor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(processor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(processor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(processor, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(processor, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(processor, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateLatencyRequirement(LatencyRequirement latencyRequirement, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (!validate_NoCircularContainment(latencyRequirement, diagnostics, context)) return false;
		boolean result = validate_EveryMultiplicityConforms(latencyRequirement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryDataValueConforms(latencyRequirement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryReferenceIsContained(latencyRequirement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryBidirectionalReferenceIsPaired(latencyRequirement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryProxyResolves(latencyRequirement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_UniqueID(latencyRequirement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryKeyUnique(latencyRequirement, diagnostics, context);
		if (result || diagnostics != null) result &= validate_EveryMapEntryUnique(latencyRequirement, diagnostics, context);
		if (result || diagnostics != null) result &= validateNamedElement_RSA21_fileNameLength(latencyRequirement, diagnostics, context);
		return result;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateArchitectureCategory(ArchitectureCategory architectureCategory, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return true;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateElementType(ElementType elementType, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return true;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateExecutionType(ExecutionType executionType, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return true;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateTimeUnit(TimeUnit timeUnit, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return true;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSynchronisationType(SynchronisationType synchronisationType, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return true;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateSchedulingPolicy(SchedulingPolicy schedulingPolicy, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return true;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateDataType(DataType dataType, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return true;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public boolean validateLatencyKind(LatencyKind latencyKind, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return true;
	}

	/**
	 * Returns the resource locator that will be used to fetch messages for this validator's diagnostics.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public ResourceLocator getResourceLocator() {
		// TODO
		// Specialize this to return a resource locator for messages specific to this validator.
		// Ensure that you remove @generated or mark it @generated NOT
		return super.getResourceLocator();
	}

} //RsamlValidator
