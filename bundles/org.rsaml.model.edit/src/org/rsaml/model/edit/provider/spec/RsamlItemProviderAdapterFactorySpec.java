/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.edit.provider.spec;

import org.eclipse.emf.common.notify.Adapter;
import org.eclipse.emf.common.notify.AdapterFactory;
import org.eclipse.emf.common.notify.Notifier;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.edit.provider.DecoratorAdapterFactory;
import org.eclipse.emf.edit.provider.IEditingDomainItemProvider;
import org.eclipse.emf.edit.provider.IItemLabelProvider;
import org.eclipse.emf.edit.provider.IItemPropertySource;
import org.eclipse.emf.edit.provider.IItemProviderDecorator;
import org.eclipse.emf.edit.provider.IStructuredItemContentProvider;
import org.eclipse.emf.edit.provider.ITreeItemContentProvider;
import org.eclipse.emf.edit.provider.ItemProviderDecorator;
import org.rsaml.model.Connection;
import org.rsaml.model.Layer;
import org.rsaml.model.Port;
import org.rsaml.model.RealTimeElement;
import org.rsaml.model.edit.RsamlEditPlugin;
import org.rsaml.model.edit.provider.RsamlItemProviderAdapterFactory;
import org.rsaml.model.support.RsamlLabels;

/**
 * RsaML's item provider factory: the generated providers, decorated in one place with labels that
 * say what an element is and how it is timed ("Module resourceChecker — real-time, 2.5 ms")
 * instead of its name alone. Registered in plugin.xml in place of the generated factory.
 */
public class RsamlItemProviderAdapterFactorySpec extends DecoratorAdapterFactory {

    public RsamlItemProviderAdapterFactorySpec() {
        super(new RsamlItemProviderAdapterFactory());
    }

    @Override
    protected IItemProviderDecorator createItemProviderDecorator(Object target, Object type) {
        return new LabelDecorator(this);
    }

    /**
     * The generated provider with RsaML's label for timed elements, layers, ports and connections;
     * everything else is the generated provider's. It declares every interface the generated
     * providers implement, since viewers ask the factory for each of them.
     */
    private static final class LabelDecorator extends ItemProviderDecorator implements Adapter, IEditingDomainItemProvider,
            IStructuredItemContentProvider, ITreeItemContentProvider, IItemLabelProvider, IItemPropertySource {

        LabelDecorator(AdapterFactory adapterFactory) {
            super(adapterFactory);
        }

        @Override
        public String getText(Object object) {
            if (object instanceof RealTimeElement || object instanceof Layer || object instanceof Port
                    || object instanceof Connection) {
                EObject element = (EObject) object;
                String type = RsamlEditPlugin.INSTANCE.getString("_UI_" + element.eClass().getName() + "_type");
                return type + " " + RsamlLabels.describe(element);
            }
            return super.getText(object);
        }

        // Adapter: the generated provider is the adapter on the element; the decorator stands in for it.
        @Override
        public Notifier getTarget() {
            return getDecoratedItemProvider() instanceof Adapter adapter ? adapter.getTarget() : null;
        }

        @Override
        public void setTarget(Notifier newTarget) {
            // the decorated provider keeps its target
        }

        @Override
        public boolean isAdapterForType(Object type) {
            return getAdapterFactory().isFactoryForType(type);
        }
    }
}
