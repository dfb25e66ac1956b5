/**
 * Copyright (c) 2026 the RsaML authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.edit.provider;


import java.util.Collection;
import java.util.List;

import org.eclipse.emf.common.notify.AdapterFactory;
import org.eclipse.emf.common.notify.Notification;

import org.eclipse.emf.ecore.EStructuralFeature;

import org.eclipse.emf.edit.provider.ComposeableAdapterFactory;
import org.eclipse.emf.edit.provider.IItemPropertyDescriptor;
import org.eclipse.emf.edit.provider.ItemPropertyDescriptor;
import org.eclipse.emf.edit.provider.ViewerNotification;

import org.rsaml.model.Architecture;
import org.rsaml.model.RsamlFactory;
import org.rsaml.model.RsamlPackage;

/**
 * This is the item provider adapter for a {@link org.rsaml.model.Architecture} object.
 * <!-- begin-user-doc -->
 * <!-- end-user-doc -->
 * @generated
 */
public class ArchitectureItemProvider extends NamedElementItemProvider {
	/**
	 * This constructs an instance from a factory and a notifier.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	public ArchitectureItemProvider(AdapterFactory adapterFactory) {
		super(adapterFactory);
	}

	/**
	 * This returns the property descriptors for the adapted class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public List<IItemPropertyDescriptor> getPropertyDescriptors(Object object) {
		if (itemPropertyDescriptors == null) {
			super.getPropertyDescriptors(object);

			addCategoryPropertyDescriptor(object);
			addDeclaredLayersPropertyDescriptor(object);
			addLifecyclePropertyDescriptor(object);
			addPackagesPropertyDescriptor(object);
		}
		return itemPropertyDescriptors;
	}

	/**
	 * This adds a property descriptor for the Category feature.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected void addCategoryPropertyDescriptor(Object object) {
		itemPropertyDescriptors.add
			(createItemPropertyDescriptor
				(((ComposeableAdapterFactory)adapterFactory).getRootAdapterFactory(),
				 getResourceLocator(),
				 getString("_UI_Architecture_category_feature"),
				 getString("_UI_PropertyDescriptor_description", "_UI_Architecture_category_feature", "_UI_Architecture_type"),
				 RsamlPackage.Literals.ARCHITECTURE__CATEGORY,
				 true,
				 false,
				 false,
				 ItemPropertyDescriptor.GENERIC_VALUE_IMAGE,
				 null,
				 null));
	}

	/**
	 * This adds a property descriptor for the Declared Layers feature.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected void addDeclaredLayersPropertyDescriptor(Object object) {
		itemPropertyDescriptors.add
			(createItemPropertyDescriptor
				(((ComposeableAdapterFactory)adapterFactory).getRootAdapterFactory(),
				 getResourceLocator(),
				 getString("_UI_Architecture_declaredLayers_feature"),
				 getString("_UI_PropertyDescriptor_description", "_UI_Architecture_declaredLayers_feature", "_UI_Architecture_type"),
				 RsamlPackage.Literals.ARCHITECTURE__DECLARED_LAYERS,
				 true,
				 false,
				 false,
				 ItemPropertyDescriptor.INTEGRAL_VALUE_IMAGE,
				 null,
				 null));
	}

	/**
	 * This adds a property descriptor for the Lifecycle feature.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected void addLifecyclePropertyDescriptor(Object object) {
		itemPropertyDescriptors.add
			(createItemPropertyDescriptor
				(((ComposeableAdapterFactory)adapterFactory).getRootAdapterFactory(),
				 getResourceLocator(),
				 getString("_UI_Architecture_lifecycle_feature"),
				 getString("_UI_PropertyDescriptor_description", "_UI_Architecture_lifecycle_feature", "_UI_Architecture_type"),
				 RsamlPackage.Literals.ARCHITECTURE__LIFECYCLE,
				 true,
				 false,
				 false,
				 ItemPropertyDescriptor.GENERIC_VALUE_IMAGE,
				 null,
				 null));
	}

	/**
	 * This adds a property descriptor for the Packages feature.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	protected void addPackagesPropertyDescriptor(Object object) {
		itemPropertyDescriptors.add
			(createItemPropertyDescriptor
				(((ComposeableAdapterFactory)adapterFactory).getRootAdapterFactory(),
				 getResourceLocator(),
				 getString("_UI_Architecture_packages_feature"),
				 getString("_UI_PropertyDescriptor_description", "_UI_Architecture_packages_feature", "_UI_Architecture_type"),
				 RsamlPackage.Literals.ARCHITECTURE__PACKAGES,
				 true,
				 false,
				 false,
				 ItemPropertyDescriptor.GENERIC_VALUE_IMAGE,
				 null,
				 null));
	}

	/**
	 * This specifies how to implement {@link #getChildren} and is used to deduce an appropriate feature for an
	 * {@link org.eclipse.emf.edit.command.AddCommand}, {@link org.eclipse.emf.edit.command.RemoveCommand} or
	 * {@link org.eclipse.emf.edit.command.MoveCommand} in {@link #createCommand}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Collection<? extends EStructuralFeature> getChildrenFeatures(Object object) {
		if (childrenFeatures == null) {
			super.getChildrenFeatures(object);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__LAYERS);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__CONNECTIONS);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__SENSORS);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__ACTUATORS);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__MISSIONS);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__SUPERVISORS);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__ORDERS);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__DATABASES);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__PROCESSORS);
			childrenFeatures.add(RsamlPackage.Literals.ARCHITECTURE__LATENCY_REQUIREMENTS);
		}
		return childrenFeatures;
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected EStructuralFeature getChildFeature(Object object, Object child) {
		// Check the type of the specified child object and return the proper feature to use for
		// adding (see {@link AddCommand}) it as a child.

		return super.getChildFeature(object, child);
	}

	/**
	 * This returns Architecture.gif.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public Object getImage(Object object) {
		return overlayImage(object, getResourceLocator().getImage("full/obj16/Architecture"));
	}

	/**
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected boolean shouldComposeCreationImage() {
		return true;
	}

	/**
	 * This returns the label text for the adapted class.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public String getText(Object object) {
		String label = ((Architecture)object).getName();
		return label == null || label.length() == 0 ?
			getString("_UI_Architecture_type") :
			getString("_UI_Architecture_type") + " " + label;
	}


	/**
	 * This handles model notifications by calling {@link #updateChildren} to update any cached
	 * children and by creating a viewer notification, which it passes to {@link #fireNotifyChanged}.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	public void notifyChanged(Notification notification) {
		updateChildren(notification);

		switch (notification.getFeatureID(Architecture.class)) {
			case RsamlPackage.ARCHITECTURE__CATEGORY:
			case RsamlPackage.ARCHITECTURE__DECLARED_LAYERS:
			case RsamlPackage.ARCHITECTURE__LIFECYCLE:
			case RsamlPackage.ARCHITECTURE__PACKAGES:
				fireNotifyChanged(new ViewerNotification(notification, notification.getNotifier(), false, true));
				return;
			case RsamlPackage.ARCHITECTURE__LAYERS:
			case RsamlPackage.ARCHITECTURE__CONNECTIONS:
			case RsamlPackage.ARCHITECTURE__SENSORS:
			case RsamlPackage.ARCHITECTURE__ACTUATORS:
			case RsamlPackage.ARCHITECTURE__MISSIONS:
			case RsamlPackage.ARCHITECTURE__SUPERVISORS:
			case RsamlPackage.ARCHITECTURE__ORDERS:
			case RsamlPackage.ARCHITECTURE__DATABASES:
			case RsamlPackage.ARCHITECTURE__PROCESSORS:
			case RsamlPackage.ARCHITECTURE__LATENCY_REQUIREMENTS:
				fireNotifyChanged(new ViewerNotification(notification, notification.getNotifier(), true, false));
				return;
		}
		super.notifyChanged(notification);
	}

	/**
	 * This adds {@link org.eclipse.emf.edit.command.CommandParameter}s describing the children
	 * that can be created under this object.
	 * <!-- begin-user-doc -->
	 * <!-- end-user-doc -->
	 * @generated
	 */
	@Override
	protected void collectNewChildDescriptors(Collection<Object> newChildDescriptors, Object object) {
		super.collectNewChildDescriptors(newChildDescriptors, object);

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__LAYERS,
				 RsamlFactory.eINSTANCE.createLayer()));

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__CONNECTIONS,
				 RsamlFactory.eINSTANCE.createConnection()));

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__SENSORS,
				 RsamlFactory.eINSTANCE.createSensor()));

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__ACTUATORS,
				 RsamlFactory.eINSTANCE.createActuator()));

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__MISSIONS,
				 RsamlFactory.eINSTANCE.createMission()));

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__SUPERVISORS,
				 RsamlFactory.eINSTANCE.createSupervisor()));

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__ORDERS,
				 RsamlFactory.eINSTANCE.createOrder()));

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__DATABASES,
				 RsamlFactory.eINSTANCE.createDatabase()));

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__PROCESSORS,
				 RsamlFactory.eINSTANCE.createProcessor()));

		newChildDescriptors.add
			(createChildParameter
				(RsamlPackage.Literals.ARCHITECTURE__LATENCY_REQUIREMENTS,
				 RsamlFactory.eINSTANCE.createLatencyRequirement()));
	}

}
