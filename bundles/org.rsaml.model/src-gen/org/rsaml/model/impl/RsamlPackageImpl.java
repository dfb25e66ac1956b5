/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.impl;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EEnum;
import org.eclipse.emf.ecore.EOperation;
import org.eclipse.emf.ecore.EPackage;
import org.eclipse.emf.ecore.EReference;

import org.eclipse.emf.ecore.impl.EPackageImpl;

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
import org.rsaml.model.NodeLifecycle;
import org.rsaml.model.Order;
import org.rsaml.model.OutputPort;
import org.rsaml.model.PackageLayout;
import org.rsaml.model.Plan;
import org.rsaml.model.Port;
import org.rsaml.model.Processor;
import org.rsaml.model.RTAction;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.RsamlFactory;
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
 * An implementation of the model <b>Package</b>.
 * <!-- end-user-doc -->
 * @generated
 */
public class RsamlPackageImpl extends EPackageImpl implements RsamlPackage {
	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass namedElementEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass timeScaledEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass realTimeElementEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass architectureEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass layerEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass moduleEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass functionEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass actionEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass rtActionEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass portEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass entryPortEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass outputPortEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass connectionEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass subsumptionLinkEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass inhibitorEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass suppressorEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass deviceEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass sensorEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass actuatorEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass missionEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass goalEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass planEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass activityEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass supervisorEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass orderEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass databaseEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass knowledgeEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass processorEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EClass latencyRequirementEClass = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum architectureCategoryEEnum = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum elementTypeEEnum = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum executionTypeEEnum = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum timeUnitEEnum = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum synchronisationTypeEEnum = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum schedulingPolicyEEnum = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum dataTypeEEnum = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum nodeLifecycleEEnum = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum packageLayoutEEnum = null;

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private EEnum latencyKindEEnum = null;

	/**
	 * Creates an instance of the model <b>Package</b>, registered with
	 * {@link org.eclipse.emf.ecore.EPackage.Registry EPackage.Registry} by the package
	 * package URI value.
	 * <p>Note: the correct way to create the package is via the static
	 * factory method {@link #init init()}, which also performs
	 * initialization of the package, or returns the registered package,
	 * if one already exists.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see org.eclipse.emf.ecore.EPackage.Registry
	 * @see org.rsaml.model.RsamlPackage#eNS_URI
	 * @see #init()
	 * @generated
	 */
	private RsamlPackageImpl() {
		super(eNS_URI, RsamlFactory.eINSTANCE);
	}
	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private static boolean isInited = false;

	/**
	 * Creates, registers, and initializes the <b>Package</b> for this model, and for any others upon which it depends.
	 *
	 * <p>This method is used to initialize {@link RsamlPackage#eINSTANCE} when that field is accessed.
	 * Clients should not invoke it directly. Instead, they should simply access that field to obtain the package.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @see #eNS_URI
	 * @see #createPackageContents()
	 * @see #initializePackageContents()
	 * @generated
	 */
	public static RsamlPackage init() {
		if (isInited) return (RsamlPackage)EPackage.Registry.INSTANCE.getEPackage(RsamlPackage.eNS_URI);

		// Obtain or create and register package
		Object registeredRsamlPackage = EPackage.Registry.INSTANCE.get(eNS_URI);
		RsamlPackageImpl theRsamlPackage = registeredRsamlPackage instanceof RsamlPackageImpl ? (RsamlPackageImpl)registeredRsamlPackage : new RsamlPackageImpl();

		isInited = true;

		// Create package meta-data objects
		theRsamlPackage.createPackageContents();

		// Initialize created meta-data
		theRsamlPackage.initializePackageContents();

		// Mark meta-data to indicate it can't be changed
		theRsamlPackage.freeze();

		// Update the registry and return the package
		EPackage.Registry.INSTANCE.put(RsamlPackage.eNS_URI, theRsamlPackage);
		return theRsamlPackage;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getNamedElement() {
		return namedElementEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getNamedElement_Name() {
		return (EAttribute)namedElementEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getNamedElement_Description() {
		return (EAttribute)namedElementEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getNamedElement__NormalizedName() {
		return namedElementEClass.getEOperations().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getTimeScaled() {
		return timeScaledEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getTimeScaled_TimeUnit() {
		return (EAttribute)timeScaledEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getTimeScaled__ToMilliseconds__double() {
		return timeScaledEClass.getEOperations().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getTimeScaled__CompareTime__double_TimeScaled_double() {
		return timeScaledEClass.getEOperations().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getTimeScaled__Representable__double() {
		return timeScaledEClass.getEOperations().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getTimeScaled__RepresentablePeriod__double() {
		return timeScaledEClass.getEOperations().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getRealTimeElement() {
		return realTimeElementEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getRealTimeElement_Type() {
		return (EAttribute)realTimeElementEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getRealTimeElement_Period() {
		return (EAttribute)realTimeElementEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getRealTimeElement_Delay() {
		return (EAttribute)realTimeElementEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getRealTimeElement_ExecDuration() {
		return (EAttribute)realTimeElementEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getRealTimeElement_ExecType() {
		return (EAttribute)realTimeElementEClass.getEStructuralFeatures().get(4);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getArchitecture() {
		return architectureEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getArchitecture_Category() {
		return (EAttribute)architectureEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getArchitecture_DeclaredLayers() {
		return (EAttribute)architectureEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getArchitecture_Lifecycle() {
		return (EAttribute)architectureEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getArchitecture_Packages() {
		return (EAttribute)architectureEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_Layers() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(4);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_Connections() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(5);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_Sensors() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(6);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_Actuators() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(7);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_Missions() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(8);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_Supervisors() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(9);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_Orders() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(10);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_Databases() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(11);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_Processors() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(12);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getArchitecture_LatencyRequirements() {
		return (EReference)architectureEClass.getEStructuralFeatures().get(13);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getLayer() {
		return layerEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getLayer_Architecture() {
		return (EReference)layerEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getLayer_Level() {
		return (EAttribute)layerEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getLayer_MaxExecTime() {
		return (EAttribute)layerEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getLayer_Modules() {
		return (EReference)layerEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getLayer__PackageProblem() {
		return layerEClass.getEOperations().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getModule() {
		return moduleEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getModule_Layer() {
		return (EReference)moduleEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getModule_Functions() {
		return (EReference)moduleEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getModule_Ports() {
		return (EReference)moduleEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getModule_Inhibitors() {
		return (EReference)moduleEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getModule_Suppressors() {
		return (EReference)moduleEClass.getEStructuralFeatures().get(4);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getModule_Sensors() {
		return (EReference)moduleEClass.getEStructuralFeatures().get(5);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getModule_Actuators() {
		return (EReference)moduleEClass.getEStructuralFeatures().get(6);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getModule_Lifecycle() {
		return (EAttribute)moduleEClass.getEStructuralFeatures().get(7);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getModule__EffectiveLifecycle() {
		return moduleEClass.getEOperations().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getFunction() {
		return functionEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getFunction_Module() {
		return (EReference)functionEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getFunction_Actions() {
		return (EReference)functionEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getFunction_SynchroType() {
		return (EAttribute)functionEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getFunction_SchedPolicy() {
		return (EAttribute)functionEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getFunction_OtherPolicy() {
		return (EAttribute)functionEClass.getEStructuralFeatures().get(4);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getAction() {
		return actionEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getAction_Function() {
		return (EReference)actionEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getAction_StartDate() {
		return (EAttribute)actionEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getRTAction() {
		return rtActionEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getPort() {
		return portEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getPort_Module() {
		return (EReference)portEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getPort_DataType() {
		return (EAttribute)portEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getPort_MessageType() {
		return (EAttribute)portEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getPort_Topic() {
		return (EAttribute)portEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getPort__NormalizedMessageType() {
		return portEClass.getEOperations().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getPort__TopicProblem() {
		return portEClass.getEOperations().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getEntryPort() {
		return entryPortEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getEntryPort_Incoming() {
		return (EReference)entryPortEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getEntryPort_SuppressedBy() {
		return (EReference)entryPortEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getOutputPort() {
		return outputPortEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getOutputPort_Outgoing() {
		return (EReference)outputPortEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getOutputPort_InhibitedBy() {
		return (EReference)outputPortEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getConnection() {
		return connectionEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getConnection_Architecture() {
		return (EReference)connectionEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getConnection_Source() {
		return (EReference)connectionEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getConnection_Target() {
		return (EReference)connectionEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getSubsumptionLink() {
		return subsumptionLinkEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getSubsumptionLink_Trigger() {
		return (EReference)subsumptionLinkEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getSubsumptionLink_Duration() {
		return (EAttribute)subsumptionLinkEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getInhibitor() {
		return inhibitorEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getInhibitor_Module() {
		return (EReference)inhibitorEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getInhibitor_Target() {
		return (EReference)inhibitorEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getSuppressor() {
		return suppressorEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getSuppressor_Module() {
		return (EReference)suppressorEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getSuppressor_Target() {
		return (EReference)suppressorEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getDevice() {
		return deviceEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getDevice_Kind() {
		return (EAttribute)deviceEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getDevice_DataType() {
		return (EAttribute)deviceEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getDevice_Period() {
		return (EAttribute)deviceEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getSensor() {
		return sensorEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getSensor_Architecture() {
		return (EReference)sensorEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getSensor_Modules() {
		return (EReference)sensorEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getActuator() {
		return actuatorEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getActuator_Architecture() {
		return (EReference)actuatorEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getActuator_Modules() {
		return (EReference)actuatorEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getMission() {
		return missionEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getMission_Architecture() {
		return (EReference)missionEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getMission_Goals() {
		return (EReference)missionEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getMission_Plans() {
		return (EReference)missionEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getGoal() {
		return goalEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getGoal_Mission() {
		return (EReference)goalEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getGoal_ParentGoal() {
		return (EReference)goalEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getGoal_SubGoals() {
		return (EReference)goalEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getGoal_Priority() {
		return (EAttribute)goalEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getPlan() {
		return planEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getPlan_Mission() {
		return (EReference)planEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getPlan_Activities() {
		return (EReference)planEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getPlan_Achieves() {
		return (EReference)planEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getActivity() {
		return activityEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getActivity_Plan() {
		return (EReference)activityEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getActivity_Actions() {
		return (EReference)activityEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getSupervisor() {
		return supervisorEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getSupervisor_Architecture() {
		return (EReference)supervisorEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getSupervisor_Plans() {
		return (EReference)supervisorEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getSupervisor_RealisedBy() {
		return (EReference)supervisorEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getOrder() {
		return orderEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getOrder_Architecture() {
		return (EReference)orderEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getOrder_Issuer() {
		return (EAttribute)orderEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getOrder_Receiver() {
		return (EReference)orderEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getOrder_Requests() {
		return (EReference)orderEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getDatabase() {
		return databaseEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getDatabase_Architecture() {
		return (EReference)databaseEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getDatabase_Knowledge() {
		return (EReference)databaseEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getKnowledge() {
		return knowledgeEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getKnowledge_Database() {
		return (EReference)knowledgeEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getKnowledge_DataType() {
		return (EAttribute)knowledgeEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getKnowledge_UsedBy() {
		return (EReference)knowledgeEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getProcessor() {
		return processorEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getProcessor_SchedPolicy() {
		return (EAttribute)processorEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getProcessor_Core() {
		return (EAttribute)processorEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getProcessor_Modules() {
		return (EReference)processorEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getProcessor_Host() {
		return (EAttribute)processorEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getProcessor_LinkLatency() {
		return (EAttribute)processorEClass.getEStructuralFeatures().get(4);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EOperation getProcessor__PackageProblem() {
		return processorEClass.getEOperations().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EClass getLatencyRequirement() {
		return latencyRequirementEClass;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getLatencyRequirement_Source() {
		return (EReference)latencyRequirementEClass.getEStructuralFeatures().get(0);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getLatencyRequirement_Target() {
		return (EReference)latencyRequirementEClass.getEStructuralFeatures().get(1);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getLatencyRequirement_MaxLatency() {
		return (EAttribute)latencyRequirementEClass.getEStructuralFeatures().get(2);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EAttribute getLatencyRequirement_Kind() {
		return (EAttribute)latencyRequirementEClass.getEStructuralFeatures().get(3);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EReference getLatencyRequirement_Via() {
		return (EReference)latencyRequirementEClass.getEStructuralFeatures().get(4);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getArchitectureCategory() {
		return architectureCategoryEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getElementType() {
		return elementTypeEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getExecutionType() {
		return executionTypeEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getTimeUnit() {
		return timeUnitEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getSynchronisationType() {
		return synchronisationTypeEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getSchedulingPolicy() {
		return schedulingPolicyEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getDataType() {
		return dataTypeEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getNodeLifecycle() {
		return nodeLifecycleEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getPackageLayout() {
		return packageLayoutEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public EEnum getLatencyKind() {
		return latencyKindEEnum;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public RsamlFactory getRsamlFactory() {
		return (RsamlFactory)getEFactoryInstance();
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private boolean isCreated = false;

	/**
	 * Creates the meta-model objects for the package.  This method is
	 * guarded to have no affect on any invocation but its first.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public void createPackageContents() {
		if (isCreated) return;
		isCreated = true;

		// Create classes and their features
		namedElementEClass = createEClass(NAMED_ELEMENT);
		createEAttribute(namedElementEClass, NAMED_ELEMENT__NAME);
		createEAttribute(namedElementEClass, NAMED_ELEMENT__DESCRIPTION);
		createEOperation(namedElementEClass, NAMED_ELEMENT___NORMALIZED_NAME);

		timeScaledEClass = createEClass(TIME_SCALED);
		createEAttribute(timeScaledEClass, TIME_SCALED__TIME_UNIT);
		createEOperation(timeScaledEClass, TIME_SCALED___TO_MILLISECONDS__DOUBLE);
		createEOperation(timeScaledEClass, TIME_SCALED___COMPARE_TIME__DOUBLE_TIMESCALED_DOUBLE);
		createEOperation(timeScaledEClass, TIME_SCALED___REPRESENTABLE__DOUBLE);
		createEOperation(timeScaledEClass, TIME_SCALED___REPRESENTABLE_PERIOD__DOUBLE);

		realTimeElementEClass = createEClass(REAL_TIME_ELEMENT);
		createEAttribute(realTimeElementEClass, REAL_TIME_ELEMENT__TYPE);
		createEAttribute(realTimeElementEClass, REAL_TIME_ELEMENT__PERIOD);
		createEAttribute(realTimeElementEClass, REAL_TIME_ELEMENT__DELAY);
		createEAttribute(realTimeElementEClass, REAL_TIME_ELEMENT__EXEC_DURATION);
		createEAttribute(realTimeElementEClass, REAL_TIME_ELEMENT__EXEC_TYPE);

		architectureEClass = createEClass(ARCHITECTURE);
		createEAttribute(architectureEClass, ARCHITECTURE__CATEGORY);
		createEAttribute(architectureEClass, ARCHITECTURE__DECLARED_LAYERS);
		createEAttribute(architectureEClass, ARCHITECTURE__LIFECYCLE);
		createEAttribute(architectureEClass, ARCHITECTURE__PACKAGES);
		createEReference(architectureEClass, ARCHITECTURE__LAYERS);
		createEReference(architectureEClass, ARCHITECTURE__CONNECTIONS);
		createEReference(architectureEClass, ARCHITECTURE__SENSORS);
		createEReference(architectureEClass, ARCHITECTURE__ACTUATORS);
		createEReference(architectureEClass, ARCHITECTURE__MISSIONS);
		createEReference(architectureEClass, ARCHITECTURE__SUPERVISORS);
		createEReference(architectureEClass, ARCHITECTURE__ORDERS);
		createEReference(architectureEClass, ARCHITECTURE__DATABASES);
		createEReference(architectureEClass, ARCHITECTURE__PROCESSORS);
		createEReference(architectureEClass, ARCHITECTURE__LATENCY_REQUIREMENTS);

		layerEClass = createEClass(LAYER);
		createEReference(layerEClass, LAYER__ARCHITECTURE);
		createEAttribute(layerEClass, LAYER__LEVEL);
		createEAttribute(layerEClass, LAYER__MAX_EXEC_TIME);
		createEReference(layerEClass, LAYER__MODULES);
		createEOperation(layerEClass, LAYER___PACKAGE_PROBLEM);

		moduleEClass = createEClass(MODULE);
		createEReference(moduleEClass, MODULE__LAYER);
		createEReference(moduleEClass, MODULE__FUNCTIONS);
		createEReference(moduleEClass, MODULE__PORTS);
		createEReference(moduleEClass, MODULE__INHIBITORS);
		createEReference(moduleEClass, MODULE__SUPPRESSORS);
		createEReference(moduleEClass, MODULE__SENSORS);
		createEReference(moduleEClass, MODULE__ACTUATORS);
		createEAttribute(moduleEClass, MODULE__LIFECYCLE);
		createEOperation(moduleEClass, MODULE___EFFECTIVE_LIFECYCLE);

		functionEClass = createEClass(FUNCTION);
		createEReference(functionEClass, FUNCTION__MODULE);
		createEReference(functionEClass, FUNCTION__ACTIONS);
		createEAttribute(functionEClass, FUNCTION__SYNCHRO_TYPE);
		createEAttribute(functionEClass, FUNCTION__SCHED_POLICY);
		createEAttribute(functionEClass, FUNCTION__OTHER_POLICY);

		actionEClass = createEClass(ACTION);
		createEReference(actionEClass, ACTION__FUNCTION);
		createEAttribute(actionEClass, ACTION__START_DATE);

		rtActionEClass = createEClass(RT_ACTION);

		portEClass = createEClass(PORT);
		createEReference(portEClass, PORT__MODULE);
		createEAttribute(portEClass, PORT__DATA_TYPE);
		createEAttribute(portEClass, PORT__MESSAGE_TYPE);
		createEAttribute(portEClass, PORT__TOPIC);
		createEOperation(portEClass, PORT___NORMALIZED_MESSAGE_TYPE);
		createEOperation(portEClass, PORT___TOPIC_PROBLEM);

		entryPortEClass = createEClass(ENTRY_PORT);
		createEReference(entryPortEClass, ENTRY_PORT__INCOMING);
		createEReference(entryPortEClass, ENTRY_PORT__SUPPRESSED_BY);

		outputPortEClass = createEClass(OUTPUT_PORT);
		createEReference(outputPortEClass, OUTPUT_PORT__OUTGOING);
		createEReference(outputPortEClass, OUTPUT_PORT__INHIBITED_BY);

		connectionEClass = createEClass(CONNECTION);
		createEReference(connectionEClass, CONNECTION__ARCHITECTURE);
		createEReference(connectionEClass, CONNECTION__SOURCE);
		createEReference(connectionEClass, CONNECTION__TARGET);

		subsumptionLinkEClass = createEClass(SUBSUMPTION_LINK);
		createEReference(subsumptionLinkEClass, SUBSUMPTION_LINK__TRIGGER);
		createEAttribute(subsumptionLinkEClass, SUBSUMPTION_LINK__DURATION);

		inhibitorEClass = createEClass(INHIBITOR);
		createEReference(inhibitorEClass, INHIBITOR__MODULE);
		createEReference(inhibitorEClass, INHIBITOR__TARGET);

		suppressorEClass = createEClass(SUPPRESSOR);
		createEReference(suppressorEClass, SUPPRESSOR__MODULE);
		createEReference(suppressorEClass, SUPPRESSOR__TARGET);

		deviceEClass = createEClass(DEVICE);
		createEAttribute(deviceEClass, DEVICE__KIND);
		createEAttribute(deviceEClass, DEVICE__DATA_TYPE);
		createEAttribute(deviceEClass, DEVICE__PERIOD);

		sensorEClass = createEClass(SENSOR);
		createEReference(sensorEClass, SENSOR__ARCHITECTURE);
		createEReference(sensorEClass, SENSOR__MODULES);

		actuatorEClass = createEClass(ACTUATOR);
		createEReference(actuatorEClass, ACTUATOR__ARCHITECTURE);
		createEReference(actuatorEClass, ACTUATOR__MODULES);

		missionEClass = createEClass(MISSION);
		createEReference(missionEClass, MISSION__ARCHITECTURE);
		createEReference(missionEClass, MISSION__GOALS);
		createEReference(missionEClass, MISSION__PLANS);

		goalEClass = createEClass(GOAL);
		createEReference(goalEClass, GOAL__MISSION);
		createEReference(goalEClass, GOAL__PARENT_GOAL);
		createEReference(goalEClass, GOAL__SUB_GOALS);
		createEAttribute(goalEClass, GOAL__PRIORITY);

		planEClass = createEClass(PLAN);
		createEReference(planEClass, PLAN__MISSION);
		createEReference(planEClass, PLAN__ACTIVITIES);
		createEReference(planEClass, PLAN__ACHIEVES);

		activityEClass = createEClass(ACTIVITY);
		createEReference(activityEClass, ACTIVITY__PLAN);
		createEReference(activityEClass, ACTIVITY__ACTIONS);

		supervisorEClass = createEClass(SUPERVISOR);
		createEReference(supervisorEClass, SUPERVISOR__ARCHITECTURE);
		createEReference(supervisorEClass, SUPERVISOR__PLANS);
		createEReference(supervisorEClass, SUPERVISOR__REALISED_BY);

		orderEClass = createEClass(ORDER);
		createEReference(orderEClass, ORDER__ARCHITECTURE);
		createEAttribute(orderEClass, ORDER__ISSUER);
		createEReference(orderEClass, ORDER__RECEIVER);
		createEReference(orderEClass, ORDER__REQUESTS);

		databaseEClass = createEClass(DATABASE);
		createEReference(databaseEClass, DATABASE__ARCHITECTURE);
		createEReference(databaseEClass, DATABASE__KNOWLEDGE);

		knowledgeEClass = createEClass(KNOWLEDGE);
		createEReference(knowledgeEClass, KNOWLEDGE__DATABASE);
		createEAttribute(knowledgeEClass, KNOWLEDGE__DATA_TYPE);
		createEReference(knowledgeEClass, KNOWLEDGE__USED_BY);

		processorEClass = createEClass(PROCESSOR);
		createEAttribute(processorEClass, PROCESSOR__SCHED_POLICY);
		createEAttribute(processorEClass, PROCESSOR__CORE);
		createEReference(processorEClass, PROCESSOR__MODULES);
		createEAttribute(processorEClass, PROCESSOR__HOST);
		createEAttribute(processorEClass, PROCESSOR__LINK_LATENCY);
		createEOperation(processorEClass, PROCESSOR___PACKAGE_PROBLEM);

		latencyRequirementEClass = createEClass(LATENCY_REQUIREMENT);
		createEReference(latencyRequirementEClass, LATENCY_REQUIREMENT__SOURCE);
		createEReference(latencyRequirementEClass, LATENCY_REQUIREMENT__TARGET);
		createEAttribute(latencyRequirementEClass, LATENCY_REQUIREMENT__MAX_LATENCY);
		createEAttribute(latencyRequirementEClass, LATENCY_REQUIREMENT__KIND);
		createEReference(latencyRequirementEClass, LATENCY_REQUIREMENT__VIA);

		// Create enums
		architectureCategoryEEnum = createEEnum(ARCHITECTURE_CATEGORY);
		elementTypeEEnum = createEEnum(ELEMENT_TYPE);
		executionTypeEEnum = createEEnum(EXECUTION_TYPE);
		timeUnitEEnum = createEEnum(TIME_UNIT);
		synchronisationTypeEEnum = createEEnum(SYNCHRONISATION_TYPE);
		schedulingPolicyEEnum = createEEnum(SCHEDULING_POLICY);
		dataTypeEEnum = createEEnum(DATA_TYPE);
		nodeLifecycleEEnum = createEEnum(NODE_LIFECYCLE);
		packageLayoutEEnum = createEEnum(PACKAGE_LAYOUT);
		latencyKindEEnum = createEEnum(LATENCY_KIND);
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	private boolean isInitialized = false;

	/**
	 * Complete the initialization of the package and its meta-model.  This
	 * method is guarded to have no affect on any invocation but its first.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public void initializePackageContents() {
		if (isInitialized) return;
		isInitialized = true;

		// Initialize package
		setName(eNAME);
		setNsPrefix(eNS_PREFIX);
		setNsURI(eNS_URI);

		// Create type parameters

		// Set bounds for type parameters

		// Add supertypes to classes
		realTimeElementEClass.getESuperTypes().add(this.getNamedElement());
		realTimeElementEClass.getESuperTypes().add(this.getTimeScaled());
		architectureEClass.getESuperTypes().add(this.getNamedElement());
		layerEClass.getESuperTypes().add(this.getNamedElement());
		layerEClass.getESuperTypes().add(this.getTimeScaled());
		moduleEClass.getESuperTypes().add(this.getRealTimeElement());
		functionEClass.getESuperTypes().add(this.getRealTimeElement());
		actionEClass.getESuperTypes().add(this.getRealTimeElement());
		rtActionEClass.getESuperTypes().add(this.getAction());
		portEClass.getESuperTypes().add(this.getNamedElement());
		entryPortEClass.getESuperTypes().add(this.getPort());
		outputPortEClass.getESuperTypes().add(this.getPort());
		subsumptionLinkEClass.getESuperTypes().add(this.getNamedElement());
		subsumptionLinkEClass.getESuperTypes().add(this.getTimeScaled());
		inhibitorEClass.getESuperTypes().add(this.getSubsumptionLink());
		suppressorEClass.getESuperTypes().add(this.getSubsumptionLink());
		deviceEClass.getESuperTypes().add(this.getNamedElement());
		deviceEClass.getESuperTypes().add(this.getTimeScaled());
		sensorEClass.getESuperTypes().add(this.getDevice());
		actuatorEClass.getESuperTypes().add(this.getDevice());
		missionEClass.getESuperTypes().add(this.getNamedElement());
		goalEClass.getESuperTypes().add(this.getNamedElement());
		planEClass.getESuperTypes().add(this.getNamedElement());
		activityEClass.getESuperTypes().add(this.getRealTimeElement());
		supervisorEClass.getESuperTypes().add(this.getNamedElement());
		orderEClass.getESuperTypes().add(this.getNamedElement());
		databaseEClass.getESuperTypes().add(this.getNamedElement());
		knowledgeEClass.getESuperTypes().add(this.getNamedElement());
		processorEClass.getESuperTypes().add(this.getNamedElement());
		processorEClass.getESuperTypes().add(this.getTimeScaled());
		latencyRequirementEClass.getESuperTypes().add(this.getNamedElement());
		latencyRequirementEClass.getESuperTypes().add(this.getTimeScaled());

		// Initialize classes, features, and operations; add parameters
		initEClass(namedElementEClass, NamedElement.class, "NamedElement", IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEAttribute(getNamedElement_Name(), ecorePackage.getEString(), "name", null, 1, 1, NamedElement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getNamedElement_Description(), ecorePackage.getEString(), "description", null, 0, 1, NamedElement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEOperation(getNamedElement__NormalizedName(), ecorePackage.getEString(), "normalizedName", 0, 1, IS_UNIQUE, IS_ORDERED);

		initEClass(timeScaledEClass, TimeScaled.class, "TimeScaled", IS_ABSTRACT, IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEAttribute(getTimeScaled_TimeUnit(), this.getTimeUnit(), "timeUnit", "ms", 0, 1, TimeScaled.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		EOperation op = initEOperation(getTimeScaled__ToMilliseconds__double(), ecorePackage.getEDouble(), "toMilliseconds", 0, 1, IS_UNIQUE, IS_ORDERED);
		addEParameter(op, ecorePackage.getEDouble(), "value", 0, 1, IS_UNIQUE, IS_ORDERED);

		op = initEOperation(getTimeScaled__CompareTime__double_TimeScaled_double(), ecorePackage.getEInt(), "compareTime", 0, 1, IS_UNIQUE, IS_ORDERED);
		addEParameter(op, ecorePackage.getEDouble(), "value", 0, 1, IS_UNIQUE, IS_ORDERED);
		addEParameter(op, this.getTimeScaled(), "other", 0, 1, IS_UNIQUE, IS_ORDERED);
		addEParameter(op, ecorePackage.getEDouble(), "otherValue", 0, 1, IS_UNIQUE, IS_ORDERED);

		op = initEOperation(getTimeScaled__Representable__double(), ecorePackage.getEBoolean(), "representable", 0, 1, IS_UNIQUE, IS_ORDERED);
		addEParameter(op, ecorePackage.getEDouble(), "value", 0, 1, IS_UNIQUE, IS_ORDERED);

		op = initEOperation(getTimeScaled__RepresentablePeriod__double(), ecorePackage.getEBoolean(), "representablePeriod", 0, 1, IS_UNIQUE, IS_ORDERED);
		addEParameter(op, ecorePackage.getEDouble(), "value", 0, 1, IS_UNIQUE, IS_ORDERED);

		initEClass(realTimeElementEClass, RealTimeElement.class, "RealTimeElement", IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEAttribute(getRealTimeElement_Type(), this.getElementType(), "type", "simple", 0, 1, RealTimeElement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getRealTimeElement_Period(), ecorePackage.getEDouble(), "period", "0.0", 0, 1, RealTimeElement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getRealTimeElement_Delay(), ecorePackage.getEDouble(), "delay", "0.0", 0, 1, RealTimeElement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getRealTimeElement_ExecDuration(), ecorePackage.getEDouble(), "execDuration", "0.0", 0, 1, RealTimeElement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getRealTimeElement_ExecType(), this.getExecutionType(), "execType", "aperiodic", 0, 1, RealTimeElement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(architectureEClass, Architecture.class, "Architecture", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEAttribute(getArchitecture_Category(), this.getArchitectureCategory(), "category", "hybrid", 0, 1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getArchitecture_DeclaredLayers(), ecorePackage.getEInt(), "declaredLayers", "0", 0, 1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getArchitecture_Lifecycle(), this.getNodeLifecycle(), "lifecycle", "plain", 0, 1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getArchitecture_Packages(), this.getPackageLayout(), "packages", "single", 0, 1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getArchitecture_Layers(), this.getLayer(), this.getLayer_Architecture(), "layers", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getArchitecture_Layers().getEKeys().add(this.getNamedElement_Name());
		initEReference(getArchitecture_Connections(), this.getConnection(), this.getConnection_Architecture(), "connections", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getArchitecture_Sensors(), this.getSensor(), this.getSensor_Architecture(), "sensors", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getArchitecture_Sensors().getEKeys().add(this.getNamedElement_Name());
		initEReference(getArchitecture_Actuators(), this.getActuator(), this.getActuator_Architecture(), "actuators", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getArchitecture_Actuators().getEKeys().add(this.getNamedElement_Name());
		initEReference(getArchitecture_Missions(), this.getMission(), this.getMission_Architecture(), "missions", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getArchitecture_Missions().getEKeys().add(this.getNamedElement_Name());
		initEReference(getArchitecture_Supervisors(), this.getSupervisor(), this.getSupervisor_Architecture(), "supervisors", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getArchitecture_Supervisors().getEKeys().add(this.getNamedElement_Name());
		initEReference(getArchitecture_Orders(), this.getOrder(), this.getOrder_Architecture(), "orders", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getArchitecture_Orders().getEKeys().add(this.getNamedElement_Name());
		initEReference(getArchitecture_Databases(), this.getDatabase(), this.getDatabase_Architecture(), "databases", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getArchitecture_Databases().getEKeys().add(this.getNamedElement_Name());
		initEReference(getArchitecture_Processors(), this.getProcessor(), null, "processors", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getArchitecture_Processors().getEKeys().add(this.getNamedElement_Name());
		initEReference(getArchitecture_LatencyRequirements(), this.getLatencyRequirement(), null, "latencyRequirements", null, 0, -1, Architecture.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getArchitecture_LatencyRequirements().getEKeys().add(this.getNamedElement_Name());

		initEClass(layerEClass, Layer.class, "Layer", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getLayer_Architecture(), this.getArchitecture(), this.getArchitecture_Layers(), "architecture", null, 0, 1, Layer.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getLayer_Level(), ecorePackage.getEInt(), "level", "0", 0, 1, Layer.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getLayer_MaxExecTime(), ecorePackage.getEDouble(), "maxExecTime", "0.0", 0, 1, Layer.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getLayer_Modules(), this.getModule(), this.getModule_Layer(), "modules", null, 0, -1, Layer.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getLayer_Modules().getEKeys().add(this.getNamedElement_Name());

		initEOperation(getLayer__PackageProblem(), ecorePackage.getEString(), "packageProblem", 0, 1, IS_UNIQUE, IS_ORDERED);

		initEClass(moduleEClass, org.rsaml.model.Module.class, "Module", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getModule_Layer(), this.getLayer(), this.getLayer_Modules(), "layer", null, 0, 1, org.rsaml.model.Module.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getModule_Functions(), this.getFunction(), this.getFunction_Module(), "functions", null, 0, -1, org.rsaml.model.Module.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getModule_Functions().getEKeys().add(this.getNamedElement_Name());
		initEReference(getModule_Ports(), this.getPort(), this.getPort_Module(), "ports", null, 0, -1, org.rsaml.model.Module.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getModule_Ports().getEKeys().add(this.getNamedElement_Name());
		initEReference(getModule_Inhibitors(), this.getInhibitor(), this.getInhibitor_Module(), "inhibitors", null, 0, -1, org.rsaml.model.Module.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getModule_Inhibitors().getEKeys().add(this.getNamedElement_Name());
		initEReference(getModule_Suppressors(), this.getSuppressor(), this.getSuppressor_Module(), "suppressors", null, 0, -1, org.rsaml.model.Module.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getModule_Suppressors().getEKeys().add(this.getNamedElement_Name());
		initEReference(getModule_Sensors(), this.getSensor(), this.getSensor_Modules(), "sensors", null, 0, -1, org.rsaml.model.Module.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getModule_Actuators(), this.getActuator(), this.getActuator_Modules(), "actuators", null, 0, -1, org.rsaml.model.Module.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getModule_Lifecycle(), this.getNodeLifecycle(), "lifecycle", null, 0, 1, org.rsaml.model.Module.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEOperation(getModule__EffectiveLifecycle(), this.getNodeLifecycle(), "effectiveLifecycle", 0, 1, IS_UNIQUE, IS_ORDERED);

		initEClass(functionEClass, Function.class, "Function", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getFunction_Module(), this.getModule(), this.getModule_Functions(), "module", null, 0, 1, Function.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getFunction_Actions(), this.getAction(), this.getAction_Function(), "actions", null, 0, -1, Function.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getFunction_Actions().getEKeys().add(this.getNamedElement_Name());
		initEAttribute(getFunction_SynchroType(), this.getSynchronisationType(), "synchroType", "synchronous", 0, 1, Function.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getFunction_SchedPolicy(), this.getSchedulingPolicy(), "schedPolicy", "FIFO", 0, 1, Function.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getFunction_OtherPolicy(), ecorePackage.getEString(), "otherPolicy", null, 0, 1, Function.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(actionEClass, Action.class, "Action", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getAction_Function(), this.getFunction(), this.getFunction_Actions(), "function", null, 0, 1, Action.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getAction_StartDate(), ecorePackage.getEDouble(), "startDate", "0.0", 0, 1, Action.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(rtActionEClass, RTAction.class, "RTAction", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);

		initEClass(portEClass, Port.class, "Port", IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getPort_Module(), this.getModule(), this.getModule_Ports(), "module", null, 0, 1, Port.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getPort_DataType(), this.getDataType(), "dataType", "numeric", 0, 1, Port.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getPort_MessageType(), ecorePackage.getEString(), "messageType", null, 0, 1, Port.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getPort_Topic(), ecorePackage.getEString(), "topic", null, 0, 1, Port.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEOperation(getPort__NormalizedMessageType(), ecorePackage.getEString(), "normalizedMessageType", 0, 1, IS_UNIQUE, IS_ORDERED);

		initEOperation(getPort__TopicProblem(), ecorePackage.getEString(), "topicProblem", 0, 1, IS_UNIQUE, IS_ORDERED);

		initEClass(entryPortEClass, EntryPort.class, "EntryPort", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getEntryPort_Incoming(), this.getConnection(), this.getConnection_Target(), "incoming", null, 0, -1, EntryPort.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getEntryPort_SuppressedBy(), this.getSuppressor(), this.getSuppressor_Target(), "suppressedBy", null, 0, -1, EntryPort.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(outputPortEClass, OutputPort.class, "OutputPort", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getOutputPort_Outgoing(), this.getConnection(), this.getConnection_Source(), "outgoing", null, 0, -1, OutputPort.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getOutputPort_InhibitedBy(), this.getInhibitor(), this.getInhibitor_Target(), "inhibitedBy", null, 0, -1, OutputPort.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(connectionEClass, Connection.class, "Connection", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getConnection_Architecture(), this.getArchitecture(), this.getArchitecture_Connections(), "architecture", null, 0, 1, Connection.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getConnection_Source(), this.getOutputPort(), this.getOutputPort_Outgoing(), "source", null, 1, 1, Connection.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getConnection_Target(), this.getEntryPort(), this.getEntryPort_Incoming(), "target", null, 1, 1, Connection.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(subsumptionLinkEClass, SubsumptionLink.class, "SubsumptionLink", IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getSubsumptionLink_Trigger(), this.getOutputPort(), null, "trigger", null, 0, 1, SubsumptionLink.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getSubsumptionLink_Duration(), ecorePackage.getEDouble(), "duration", "0.0", 0, 1, SubsumptionLink.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(inhibitorEClass, Inhibitor.class, "Inhibitor", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getInhibitor_Module(), this.getModule(), this.getModule_Inhibitors(), "module", null, 0, 1, Inhibitor.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getInhibitor_Target(), this.getOutputPort(), this.getOutputPort_InhibitedBy(), "target", null, 1, 1, Inhibitor.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(suppressorEClass, Suppressor.class, "Suppressor", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getSuppressor_Module(), this.getModule(), this.getModule_Suppressors(), "module", null, 0, 1, Suppressor.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getSuppressor_Target(), this.getEntryPort(), this.getEntryPort_SuppressedBy(), "target", null, 1, 1, Suppressor.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(deviceEClass, Device.class, "Device", IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEAttribute(getDevice_Kind(), ecorePackage.getEString(), "kind", null, 0, 1, Device.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getDevice_DataType(), this.getDataType(), "dataType", "numeric", 0, 1, Device.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getDevice_Period(), ecorePackage.getEDouble(), "period", "0.0", 0, 1, Device.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(sensorEClass, Sensor.class, "Sensor", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getSensor_Architecture(), this.getArchitecture(), this.getArchitecture_Sensors(), "architecture", null, 0, 1, Sensor.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getSensor_Modules(), this.getModule(), this.getModule_Sensors(), "modules", null, 0, -1, Sensor.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(actuatorEClass, Actuator.class, "Actuator", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getActuator_Architecture(), this.getArchitecture(), this.getArchitecture_Actuators(), "architecture", null, 0, 1, Actuator.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getActuator_Modules(), this.getModule(), this.getModule_Actuators(), "modules", null, 0, -1, Actuator.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(missionEClass, Mission.class, "Mission", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getMission_Architecture(), this.getArchitecture(), this.getArchitecture_Missions(), "architecture", null, 0, 1, Mission.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getMission_Goals(), this.getGoal(), this.getGoal_Mission(), "goals", null, 0, -1, Mission.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getMission_Goals().getEKeys().add(this.getNamedElement_Name());
		initEReference(getMission_Plans(), this.getPlan(), this.getPlan_Mission(), "plans", null, 0, -1, Mission.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getMission_Plans().getEKeys().add(this.getNamedElement_Name());

		initEClass(goalEClass, Goal.class, "Goal", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getGoal_Mission(), this.getMission(), this.getMission_Goals(), "mission", null, 0, 1, Goal.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getGoal_ParentGoal(), this.getGoal(), this.getGoal_SubGoals(), "parentGoal", null, 0, 1, Goal.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getGoal_SubGoals(), this.getGoal(), this.getGoal_ParentGoal(), "subGoals", null, 0, -1, Goal.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getGoal_SubGoals().getEKeys().add(this.getNamedElement_Name());
		initEAttribute(getGoal_Priority(), ecorePackage.getEInt(), "priority", "0", 0, 1, Goal.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(planEClass, Plan.class, "Plan", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getPlan_Mission(), this.getMission(), this.getMission_Plans(), "mission", null, 0, 1, Plan.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getPlan_Activities(), this.getActivity(), this.getActivity_Plan(), "activities", null, 0, -1, Plan.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getPlan_Activities().getEKeys().add(this.getNamedElement_Name());
		initEReference(getPlan_Achieves(), this.getGoal(), null, "achieves", null, 0, -1, Plan.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(activityEClass, Activity.class, "Activity", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getActivity_Plan(), this.getPlan(), this.getPlan_Activities(), "plan", null, 0, 1, Activity.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getActivity_Actions(), this.getAction(), null, "actions", null, 0, -1, Activity.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(supervisorEClass, Supervisor.class, "Supervisor", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getSupervisor_Architecture(), this.getArchitecture(), this.getArchitecture_Supervisors(), "architecture", null, 0, 1, Supervisor.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getSupervisor_Plans(), this.getPlan(), null, "plans", null, 0, -1, Supervisor.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getSupervisor_RealisedBy(), this.getModule(), null, "realisedBy", null, 0, 1, Supervisor.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(orderEClass, Order.class, "Order", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getOrder_Architecture(), this.getArchitecture(), this.getArchitecture_Orders(), "architecture", null, 0, 1, Order.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getOrder_Issuer(), ecorePackage.getEString(), "issuer", null, 0, 1, Order.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getOrder_Receiver(), this.getModule(), null, "receiver", null, 0, 1, Order.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getOrder_Requests(), this.getActivity(), null, "requests", null, 0, 1, Order.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(databaseEClass, Database.class, "Database", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getDatabase_Architecture(), this.getArchitecture(), this.getArchitecture_Databases(), "architecture", null, 0, 1, Database.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getDatabase_Knowledge(), this.getKnowledge(), this.getKnowledge_Database(), "knowledge", null, 0, -1, Database.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		getDatabase_Knowledge().getEKeys().add(this.getNamedElement_Name());

		initEClass(knowledgeEClass, Knowledge.class, "Knowledge", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getKnowledge_Database(), this.getDatabase(), this.getDatabase_Knowledge(), "database", null, 0, 1, Knowledge.class, IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, !IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getKnowledge_DataType(), this.getDataType(), "dataType", "structured", 0, 1, Knowledge.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getKnowledge_UsedBy(), this.getModule(), null, "usedBy", null, 0, -1, Knowledge.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEClass(processorEClass, Processor.class, "Processor", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEAttribute(getProcessor_SchedPolicy(), this.getSchedulingPolicy(), "schedPolicy", null, 0, 1, Processor.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getProcessor_Core(), ecorePackage.getEInt(), "core", "-1", 0, 1, Processor.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getProcessor_Modules(), this.getModule(), null, "modules", null, 0, -1, Processor.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getProcessor_Host(), ecorePackage.getEString(), "host", null, 0, 1, Processor.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getProcessor_LinkLatency(), ecorePackage.getEDouble(), "linkLatency", null, 0, 1, Processor.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		initEOperation(getProcessor__PackageProblem(), ecorePackage.getEString(), "packageProblem", 0, 1, IS_UNIQUE, IS_ORDERED);

		initEClass(latencyRequirementEClass, LatencyRequirement.class, "LatencyRequirement", !IS_ABSTRACT, !IS_INTERFACE, IS_GENERATED_INSTANCE_CLASS);
		initEReference(getLatencyRequirement_Source(), this.getNamedElement(), null, "source", null, 1, 1, LatencyRequirement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getLatencyRequirement_Target(), this.getNamedElement(), null, "target", null, 1, 1, LatencyRequirement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getLatencyRequirement_MaxLatency(), ecorePackage.getEDouble(), "maxLatency", "0.0", 0, 1, LatencyRequirement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEAttribute(getLatencyRequirement_Kind(), this.getLatencyKind(), "kind", "reactionTime", 0, 1, LatencyRequirement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_UNSETTABLE, !IS_ID, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);
		initEReference(getLatencyRequirement_Via(), this.getNamedElement(), null, "via", null, 0, -1, LatencyRequirement.class, !IS_TRANSIENT, !IS_VOLATILE, IS_CHANGEABLE, !IS_COMPOSITE, IS_RESOLVE_PROXIES, !IS_UNSETTABLE, IS_UNIQUE, !IS_DERIVED, IS_ORDERED);

		// Initialize enums and add enum literals
		initEEnum(architectureCategoryEEnum, ArchitectureCategory.class, "ArchitectureCategory");
		addEEnumLiteral(architectureCategoryEEnum, ArchitectureCategory.CENTRALIZED);
		addEEnumLiteral(architectureCategoryEEnum, ArchitectureCategory.HIERARCHICAL);
		addEEnumLiteral(architectureCategoryEEnum, ArchitectureCategory.BEHAVIORAL);
		addEEnumLiteral(architectureCategoryEEnum, ArchitectureCategory.HYBRID);
		addEEnumLiteral(architectureCategoryEEnum, ArchitectureCategory.OTHER);

		initEEnum(elementTypeEEnum, ElementType.class, "ElementType");
		addEEnumLiteral(elementTypeEEnum, ElementType.SIMPLE);
		addEEnumLiteral(elementTypeEEnum, ElementType.REAL_TIME);

		initEEnum(executionTypeEEnum, ExecutionType.class, "ExecutionType");
		addEEnumLiteral(executionTypeEEnum, ExecutionType.PERIODIC);
		addEEnumLiteral(executionTypeEEnum, ExecutionType.SPORADIC);
		addEEnumLiteral(executionTypeEEnum, ExecutionType.APERIODIC);

		initEEnum(timeUnitEEnum, TimeUnit.class, "TimeUnit");
		addEEnumLiteral(timeUnitEEnum, TimeUnit.NS);
		addEEnumLiteral(timeUnitEEnum, TimeUnit.US);
		addEEnumLiteral(timeUnitEEnum, TimeUnit.MS);
		addEEnumLiteral(timeUnitEEnum, TimeUnit.S);

		initEEnum(synchronisationTypeEEnum, SynchronisationType.class, "SynchronisationType");
		addEEnumLiteral(synchronisationTypeEEnum, SynchronisationType.SYNCHRONOUS);
		addEEnumLiteral(synchronisationTypeEEnum, SynchronisationType.ASYNCHRONOUS);

		initEEnum(schedulingPolicyEEnum, SchedulingPolicy.class, "SchedulingPolicy");
		addEEnumLiteral(schedulingPolicyEEnum, SchedulingPolicy.FIFO);
		addEEnumLiteral(schedulingPolicyEEnum, SchedulingPolicy.SJF);
		addEEnumLiteral(schedulingPolicyEEnum, SchedulingPolicy.RR);
		addEEnumLiteral(schedulingPolicyEEnum, SchedulingPolicy.RM);
		addEEnumLiteral(schedulingPolicyEEnum, SchedulingPolicy.DM);
		addEEnumLiteral(schedulingPolicyEEnum, SchedulingPolicy.EDF);
		addEEnumLiteral(schedulingPolicyEEnum, SchedulingPolicy.LLF);
		addEEnumLiteral(schedulingPolicyEEnum, SchedulingPolicy.OTHER);

		initEEnum(dataTypeEEnum, DataType.class, "DataType");
		addEEnumLiteral(dataTypeEEnum, DataType.NUMERIC);
		addEEnumLiteral(dataTypeEEnum, DataType.ALPHANUMERIC);
		addEEnumLiteral(dataTypeEEnum, DataType.BOOLEAN);
		addEEnumLiteral(dataTypeEEnum, DataType.STRUCTURED);

		initEEnum(nodeLifecycleEEnum, NodeLifecycle.class, "NodeLifecycle");
		addEEnumLiteral(nodeLifecycleEEnum, NodeLifecycle.PLAIN);
		addEEnumLiteral(nodeLifecycleEEnum, NodeLifecycle.MANAGED);

		initEEnum(packageLayoutEEnum, PackageLayout.class, "PackageLayout");
		addEEnumLiteral(packageLayoutEEnum, PackageLayout.SINGLE);
		addEEnumLiteral(packageLayoutEEnum, PackageLayout.PER_LAYER);
		addEEnumLiteral(packageLayoutEEnum, PackageLayout.PER_PROCESSOR);

		initEEnum(latencyKindEEnum, LatencyKind.class, "LatencyKind");
		addEEnumLiteral(latencyKindEEnum, LatencyKind.REACTION_TIME);
		addEEnumLiteral(latencyKindEEnum, LatencyKind.DATA_AGE);

		// Create resource
		createResource(eNS_URI);

		// Create annotations
		// http://www.eclipse.org/emf/2002/Ecore
		createEcoreAnnotations();
		// http://www.eclipse.org/emf/2002/Ecore/OCL
		createOCLAnnotations();
	}

	/**
	 * Initializes the annotations for <b>http://www.eclipse.org/emf/2002/Ecore</b>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected void createEcoreAnnotations() {
		String source = "http://www.eclipse.org/emf/2002/Ecore";
		addAnnotation
		  (this,
		   source,
		   new String[] {
			   "invocationDelegates", "http://www.eclipse.org/emf/2002/Ecore/OCL",
			   "settingDelegates", "http://www.eclipse.org/emf/2002/Ecore/OCL"
		   });
		addAnnotation
		  (namedElementEClass,
		   source,
		   new String[] {
			   "constraints", "RSA21_fileNameLength"
		   });
		addAnnotation
		  (realTimeElementEClass,
		   source,
		   new String[] {
			   "constraints", "RSA10_executionWithinPeriod RSA11_deadlineWithinPeriod RSA12_periodicHasPeriod RSA13_nonNegativeTimes RSA17_executionWithinDeadline RSA20_representableTimes"
		   });
		addAnnotation
		  (architectureEClass,
		   source,
		   new String[] {
			   "constraints", "RSA01_declaredLayerCount RSA09_uniqueNames RSA14_layerLevels"
		   });
		addAnnotation
		  (layerEClass,
		   source,
		   new String[] {
			   "constraints", "RSA09_uniqueNames RSA13_nonNegativeTimes RSA20_representableTimes RSA29_packageNameUsable"
		   });
		addAnnotation
		  (moduleEClass,
		   source,
		   new String[] {
			   "constraints", "RSA05_realTimeModuleTiming RSA06_realTimeModuleFunctions RSA08_layerExecutionBudget RSA09_uniqueNames RSA19_activatedModule"
		   });
		addAnnotation
		  (functionEClass,
		   source,
		   new String[] {
			   "constraints", "RSA07_realTimeFunctionActions RSA09_uniqueNames RSA27_functionWithinBudget"
		   });
		addAnnotation
		  (actionEClass,
		   source,
		   new String[] {
			   "constraints", "RSA27_actionWithinBudget"
		   });
		addAnnotation
		  (rtActionEClass,
		   source,
		   new String[] {
			   "constraints", "RSA15_rtActionIsRealTime"
		   });
		addAnnotation
		  (portEClass,
		   source,
		   new String[] {
			   "constraints", "RSA18_structuredPortNamesMessageType RSA28_topicNameUsable"
		   });
		addAnnotation
		  (connectionEClass,
		   source,
		   new String[] {
			   "constraints", "RSA02_connectedPortTypes RSA03_adjacentLayerCommunication"
		   });
		addAnnotation
		  (subsumptionLinkEClass,
		   source,
		   new String[] {
			   "constraints", "RSA13_nonNegativeTimes RSA20_representableTimes RSA26_durationBelowTriggerPeriod"
		   });
		addAnnotation
		  (inhibitorEClass,
		   source,
		   new String[] {
			   "constraints", "RSA04_inhibitLayerBelow RSA16_triggerOfOwnModule"
		   });
		addAnnotation
		  (suppressorEClass,
		   source,
		   new String[] {
			   "constraints", "RSA04_suppressLayerBelow RSA16_triggerOfOwnModule"
		   });
		addAnnotation
		  (deviceEClass,
		   source,
		   new String[] {
			   "constraints", "RSA13_nonNegativeTimes RSA20_representableTimes"
		   });
		addAnnotation
		  (missionEClass,
		   source,
		   new String[] {
			   "constraints", "RSA09_uniqueNames"
		   });
		addAnnotation
		  (goalEClass,
		   source,
		   new String[] {
			   "constraints", "RSA09_uniqueNames"
		   });
		addAnnotation
		  (planEClass,
		   source,
		   new String[] {
			   "constraints", "RSA09_uniqueNames"
		   });
		addAnnotation
		  (databaseEClass,
		   source,
		   new String[] {
			   "constraints", "RSA09_uniqueNames"
		   });
		addAnnotation
		  (processorEClass,
		   source,
		   new String[] {
			   "constraints", "RSA13_nonNegativeTimes RSA20_representableTimes RSA29_packageNameUsable"
		   });
	}

	/**
	 * Initializes the annotations for <b>http://www.eclipse.org/emf/2002/Ecore/OCL</b>.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected void createOCLAnnotations() {
		String source = "http://www.eclipse.org/emf/2002/Ecore/OCL";
		addAnnotation
		  (namedElementEClass,
		   source,
		   new String[] {
			   "RSA21_fileNameLength", "(normalizedName() = null or normalizedName().size() <= 100) and (oclIsKindOf(Port) implies (oclAsType(Port).normalizedMessageType() = null or oclAsType(Port).normalizedMessageType().size() <= 100))"
		   });
		addAnnotation
		  (realTimeElementEClass,
		   source,
		   new String[] {
			   "RSA10_executionWithinPeriod", "(execType = ExecutionType::periodic and period > 0) implies execDuration <= period",
			   "RSA11_deadlineWithinPeriod", "(execType = ExecutionType::periodic and period > 0 and delay > 0) implies delay <= period",
			   "RSA12_periodicHasPeriod", "execType = ExecutionType::periodic implies period > 0",
			   "RSA13_nonNegativeTimes", "period >= 0 and delay >= 0 and execDuration >= 0",
			   "RSA17_executionWithinDeadline", "(type = ElementType::realTime and delay > 0) implies execDuration <= delay",
			   "RSA20_representableTimes", "representablePeriod(period) and representable(delay) and representable(execDuration)"
		   });
		addAnnotation
		  (architectureEClass,
		   source,
		   new String[] {
			   "RSA01_declaredLayerCount", "declaredLayers = layers->size()",
			   "RSA09_uniqueNames", "layers->isUnique(normalizedName()) and sensors->isUnique(normalizedName()) and actuators->isUnique(normalizedName()) and missions->isUnique(normalizedName()) and supervisors->isUnique(normalizedName()) and orders->isUnique(normalizedName()) and databases->isUnique(normalizedName())",
			   "RSA14_layerLevels", "layers->isUnique(level) and layers->forAll(l | l.level >= 0 and l.level < layers->size())"
		   });
		addAnnotation
		  (layerEClass,
		   source,
		   new String[] {
			   "RSA09_uniqueNames", "modules->isUnique(normalizedName())",
			   "RSA13_nonNegativeTimes", "maxExecTime >= 0",
			   "RSA20_representableTimes", "representable(maxExecTime)",
			   "RSA29_packageNameUsable", "packageProblem() = null"
		   });
		addAnnotation
		  (moduleEClass,
		   source,
		   new String[] {
			   "RSA05_realTimeModuleTiming", "type = ElementType::realTime implies (period > 0 and delay > 0)",
			   "RSA06_realTimeModuleFunctions", "type = ElementType::realTime implies functions->forAll(f | f.type = ElementType::realTime)",
			   "RSA08_layerExecutionBudget", "(layer <> null and layer.maxExecTime > 0) implies compareTime(execDuration, layer, layer.maxExecTime) <= 0",
			   "RSA09_uniqueNames", "ports->isUnique(normalizedName()) and functions->isUnique(normalizedName()) and inhibitors->isUnique(normalizedName()) and suppressors->isUnique(normalizedName())",
			   "RSA19_activatedModule", "Set{self}->closure(m | m.ports->select(p | p.oclIsKindOf(EntryPort) and not ((m.execType = ExecutionType::periodic and m.period > 0) or m.functions->exists(f | (f.execType = ExecutionType::periodic and f.period > 0) or f.actions->exists(a | a.execType = ExecutionType::periodic and a.period > 0))))->collect(p | p.oclAsType(EntryPort))->collect(e | e.incoming->select(c | c.source <> null and c.source.module <> null and c.source.dataType = e.dataType and (e.dataType = DataType::structured implies c.source.normalizedMessageType() = e.normalizedMessageType()))->collect(c | c.source.module)->union(e.suppressedBy->select(s | s.trigger <> null and s.trigger.module <> null and s.trigger.dataType = e.dataType and (e.dataType = DataType::structured implies s.trigger.normalizedMessageType() = e.normalizedMessageType()))->collect(s | s.trigger.module))))->including(self)->exists(m | (m.execType = ExecutionType::periodic and m.period > 0) or m.functions->exists(f | (f.execType = ExecutionType::periodic and f.period > 0) or f.actions->exists(a | a.execType = ExecutionType::periodic and a.period > 0)))"
		   });
		addAnnotation
		  (functionEClass,
		   source,
		   new String[] {
			   "RSA07_realTimeFunctionActions", "type = ElementType::realTime implies actions->forAll(a | a.type = ElementType::realTime)",
			   "RSA09_uniqueNames", "actions->isUnique(normalizedName())",
			   "RSA27_functionWithinBudget", "(module <> null and module.execDuration > 0 implies compareTime(execDuration, module, module.execDuration) <= 0) and ((module <> null and module.layer <> null and module.layer.maxExecTime > 0) implies compareTime(execDuration, module.layer, module.layer.maxExecTime) <= 0)"
		   });
		addAnnotation
		  (actionEClass,
		   source,
		   new String[] {
			   "RSA27_actionWithinBudget", "(function <> null and function.execDuration > 0 implies compareTime(execDuration, function, function.execDuration) <= 0) and ((function <> null and function.module <> null and function.module.execDuration > 0) implies compareTime(execDuration, function.module, function.module.execDuration) <= 0) and ((function <> null and function.module <> null and function.module.layer <> null and function.module.layer.maxExecTime > 0) implies compareTime(execDuration, function.module.layer, function.module.layer.maxExecTime) <= 0)"
		   });
		addAnnotation
		  (rtActionEClass,
		   source,
		   new String[] {
			   "RSA15_rtActionIsRealTime", "type = ElementType::realTime"
		   });
		addAnnotation
		  (portEClass,
		   source,
		   new String[] {
			   "RSA18_structuredPortNamesMessageType", "dataType = DataType::structured implies normalizedMessageType() <> null",
			   "RSA28_topicNameUsable", "topicProblem() = null"
		   });
		addAnnotation
		  (connectionEClass,
		   source,
		   new String[] {
			   "RSA02_connectedPortTypes", "(source <> null and target <> null) implies (source.dataType = target.dataType and (source.dataType = DataType::structured implies source.normalizedMessageType() = target.normalizedMessageType()))",
			   "RSA03_adjacentLayerCommunication", "let from : Layer = if source = null or source.module = null then null else source.module.layer endif, to : Layer = if target = null or target.module = null then null else target.module.layer endif in (from <> null and to <> null) implies (from.level - to.level).abs() <= 1"
		   });
		addAnnotation
		  (subsumptionLinkEClass,
		   source,
		   new String[] {
			   "RSA13_nonNegativeTimes", "duration >= 0",
			   "RSA20_representableTimes", "representable(duration)",
			   "RSA26_durationBelowTriggerPeriod", "(trigger <> null and trigger.module <> null and duration > 0) implies (((trigger.module.execType = ExecutionType::periodic and trigger.module.period > 0) and (trigger.module.functions->exists(f | not (f.execType = ExecutionType::periodic and f.period > 0)) or not trigger.module.functions->exists(f | (f.execType = ExecutionType::periodic and f.period > 0) or f.actions->exists(a | (a.execType = ExecutionType::periodic and a.period > 0)))) implies trigger.module.compareTime(trigger.module.period, self, duration) > 0) and trigger.module.functions->forAll(f | (f.execType = ExecutionType::periodic and f.period > 0) implies f.compareTime(f.period, self, duration) > 0) and trigger.module.functions->forAll(f | f.actions->forAll(a | (a.execType = ExecutionType::periodic and a.period > 0) implies a.compareTime(a.period, self, duration) > 0)))"
		   });
		addAnnotation
		  (inhibitorEClass,
		   source,
		   new String[] {
			   "RSA04_inhibitLayerBelow", "let own : Layer = if module = null then null else module.layer endif, other : Layer = if target = null or target.module = null then null else target.module.layer endif in (own <> null and other <> null) implies other.level = own.level - 1",
			   "RSA16_triggerOfOwnModule", "trigger <> null implies trigger.module = module"
		   });
		addAnnotation
		  (suppressorEClass,
		   source,
		   new String[] {
			   "RSA04_suppressLayerBelow", "let own : Layer = if module = null then null else module.layer endif, other : Layer = if target = null or target.module = null then null else target.module.layer endif in (own <> null and other <> null) implies other.level = own.level - 1",
			   "RSA16_triggerOfOwnModule", "trigger <> null implies trigger.module = module"
		   });
		addAnnotation
		  (deviceEClass,
		   source,
		   new String[] {
			   "RSA13_nonNegativeTimes", "period >= 0",
			   "RSA20_representableTimes", "representablePeriod(period)"
		   });
		addAnnotation
		  (missionEClass,
		   source,
		   new String[] {
			   "RSA09_uniqueNames", "goals->isUnique(normalizedName()) and plans->isUnique(normalizedName())"
		   });
		addAnnotation
		  (goalEClass,
		   source,
		   new String[] {
			   "RSA09_uniqueNames", "subGoals->isUnique(normalizedName())"
		   });
		addAnnotation
		  (planEClass,
		   source,
		   new String[] {
			   "RSA09_uniqueNames", "activities->isUnique(normalizedName())"
		   });
		addAnnotation
		  (databaseEClass,
		   source,
		   new String[] {
			   "RSA09_uniqueNames", "knowledge->isUnique(normalizedName())"
		   });
		addAnnotation
		  (processorEClass,
		   source,
		   new String[] {
			   "RSA13_nonNegativeTimes", "linkLatency >= 0",
			   "RSA20_representableTimes", "representable(linkLatency)",
			   "RSA29_packageNameUsable", "packageProblem() = null"
		   });
	}

} //RsamlPackageImpl
