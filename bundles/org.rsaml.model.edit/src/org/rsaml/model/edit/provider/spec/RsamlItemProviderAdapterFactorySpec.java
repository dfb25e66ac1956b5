/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.edit.provider.spec;

import org.eclipse.emf.common.notify.AdapterFactory;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.edit.provider.DecoratorAdapterFactory;
import org.eclipse.emf.edit.provider.IItemLabelProvider;
import org.eclipse.emf.edit.provider.IItemProviderDecorator;
import org.eclipse.emf.edit.provider.ItemProviderAdapter;
import org.eclipse.emf.edit.provider.ItemProviderDecorator;
import org.rsaml.model.Connection;
import org.rsaml.model.Layer;
import org.rsaml.model.Port;
import org.rsaml.model.RealTimeElement;
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

    /** The generated provider with RsaML's label for timed elements, layers, ports and connections. */
    private static final class LabelDecorator extends ItemProviderDecorator implements IItemLabelProvider {

        LabelDecorator(AdapterFactory adapterFactory) {
            super(adapterFactory);
        }

        @Override
        public String getText(Object object) {
            if ((object instanceof RealTimeElement || object instanceof Layer || object instanceof Port
                    || object instanceof Connection) && getDecoratedItemProvider() instanceof ItemProviderAdapter generated) {
                EObject element = (EObject) object;
                String type = generated.getResourceLocator().getString("_UI_" + element.eClass().getName() + "_type");
                return type + " " + RsamlLabels.describe(element);
            }
            return super.getText(object);
        }
    }
}
