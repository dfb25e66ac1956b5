/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.notify.Notification;
import org.eclipse.emf.common.notify.Notifier;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EContentAdapter;
import org.eclipse.emf.ecore.util.EcoreUtil;

/**
 * RsaML's findings on each element of a model, computed once per model change: diagrams ask for
 * the findings of every element they draw, and validating the whole model for each would cost a
 * validation per element and per refresh. The cache is an adapter on the element's resource (or,
 * outside a resource, on its root) and is dropped by any change to the model's contents.
 */
public final class DiagnosisCache extends EContentAdapter {

    private Map<EObject, List<Diagnostic>> byElement;

    private DiagnosisCache() {
    }

    /**
     * The findings whose element is {@code element} itself (not those on what it contains), as
     * {@link RsamlModelValidator#diagnose(EObject)} words them; the same list until the model changes.
     */
    public static List<Diagnostic> on(EObject element) {
        Resource resource = element.eResource();
        Notifier holder = resource != null ? resource : EcoreUtil.getRootContainer(element);
        DiagnosisCache cache = null;
        for (Object adapter : holder.eAdapters()) {
            if (adapter instanceof DiagnosisCache c) {
                cache = c;
            }
        }
        if (cache == null) {
            cache = new DiagnosisCache();
            holder.eAdapters().add(cache);
        }
        return cache.findings(holder).getOrDefault(element, List.of());
    }

    private synchronized Map<EObject, List<Diagnostic>> findings(Notifier holder) {
        if (byElement == null) {
            Map<EObject, List<Diagnostic>> map = new HashMap<>();
            List<EObject> roots = holder instanceof Resource r ? r.getContents() : List.of((EObject) holder);
            for (EObject root : new ArrayList<>(roots)) {
                for (Diagnostic d : RsamlModelValidator.diagnose(root).getChildren()) {
                    if (!d.getData().isEmpty() && d.getData().get(0) instanceof EObject on) {
                        map.computeIfAbsent(on, k -> new ArrayList<>()).add(d);
                    }
                }
            }
            map.replaceAll((k, v) -> List.copyOf(v));
            byElement = map;
        }
        return byElement;
    }

    @Override
    public void notifyChanged(Notification notification) {
        super.notifyChanged(notification);
        boolean resourceState = notification.getNotifier() instanceof Resource
                && notification.getFeatureID(Resource.class) != Resource.RESOURCE__CONTENTS;
        if (!notification.isTouch() && !resourceState) {
            synchronized (this) {
                byElement = null;
            }
        }
    }
}
