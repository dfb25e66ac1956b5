/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.edit.provider.spec;

import org.eclipse.emf.common.notify.Adapter;
import org.eclipse.emf.ecore.EObject;
import org.rsaml.model.edit.provider.ActionItemProvider;
import org.rsaml.model.edit.provider.ActivityItemProvider;
import org.rsaml.model.edit.provider.ConnectionItemProvider;
import org.rsaml.model.edit.provider.EntryPortItemProvider;
import org.rsaml.model.edit.provider.FunctionItemProvider;
import org.rsaml.model.edit.provider.LayerItemProvider;
import org.rsaml.model.edit.provider.ModuleItemProvider;
import org.rsaml.model.edit.provider.OutputPortItemProvider;
import org.rsaml.model.edit.provider.RTActionItemProvider;
import org.rsaml.model.edit.provider.RsamlItemProviderAdapterFactory;
import org.rsaml.model.support.RsamlLabels;

/**
 * RsaML's item provider factory: the generated providers, with labels that say what an element
 * is and how it is timed ("Module resourceChecker — real-time, 2.5 ms") instead of its name alone.
 * Registered in plugin.xml in place of the generated factory.
 */
public class RsamlItemProviderAdapterFactorySpec extends RsamlItemProviderAdapterFactory {

    static String label(String typeName, Object object) {
        return typeName + " " + RsamlLabels.describe((EObject) object);
    }

    @Override
    public Adapter createLayerAdapter() {
        if (layerItemProvider == null) {
            layerItemProvider = new LayerItemProvider(this) {
                @Override
                public String getText(Object object) {
                    return label(getString("_UI_Layer_type"), object);
                }
            };
        }
        return layerItemProvider;
    }

    @Override
    public Adapter createModuleAdapter() {
        if (moduleItemProvider == null) {
            moduleItemProvider = new ModuleItemProvider(this) {
                @Override
                public String getText(Object object) {
                    return label(getString("_UI_Module_type"), object);
                }
            };
        }
        return moduleItemProvider;
    }

    @Override
    public Adapter createFunctionAdapter() {
        if (functionItemProvider == null) {
            functionItemProvider = new FunctionItemProvider(this) {
                @Override
                public String getText(Object object) {
                    return label(getString("_UI_Function_type"), object);
                }
            };
        }
        return functionItemProvider;
    }

    @Override
    public Adapter createActionAdapter() {
        if (actionItemProvider == null) {
            actionItemProvider = new ActionItemProvider(this) {
                @Override
                public String getText(Object object) {
                    return label(getString("_UI_Action_type"), object);
                }
            };
        }
        return actionItemProvider;
    }

    @Override
    public Adapter createRTActionAdapter() {
        if (rtActionItemProvider == null) {
            rtActionItemProvider = new RTActionItemProvider(this) {
                @Override
                public String getText(Object object) {
                    return label(getString("_UI_RTAction_type"), object);
                }
            };
        }
        return rtActionItemProvider;
    }

    @Override
    public Adapter createActivityAdapter() {
        if (activityItemProvider == null) {
            activityItemProvider = new ActivityItemProvider(this) {
                @Override
                public String getText(Object object) {
                    return label(getString("_UI_Activity_type"), object);
                }
            };
        }
        return activityItemProvider;
    }

    @Override
    public Adapter createEntryPortAdapter() {
        if (entryPortItemProvider == null) {
            entryPortItemProvider = new EntryPortItemProvider(this) {
                @Override
                public String getText(Object object) {
                    return label(getString("_UI_EntryPort_type"), object);
                }
            };
        }
        return entryPortItemProvider;
    }

    @Override
    public Adapter createOutputPortAdapter() {
        if (outputPortItemProvider == null) {
            outputPortItemProvider = new OutputPortItemProvider(this) {
                @Override
                public String getText(Object object) {
                    return label(getString("_UI_OutputPort_type"), object);
                }
            };
        }
        return outputPortItemProvider;
    }

    @Override
    public Adapter createConnectionAdapter() {
        if (connectionItemProvider == null) {
            connectionItemProvider = new ConnectionItemProvider(this) {
                @Override
                public String getText(Object object) {
                    return label(getString("_UI_Connection_type"), object);
                }
            };
        }
        return connectionItemProvider;
    }
}
