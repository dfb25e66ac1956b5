/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.services;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.TreeIterator;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.rsaml.model.Action;
import org.rsaml.model.Architecture;
import org.rsaml.model.Connection;
import org.rsaml.model.Mission;
import org.rsaml.model.NamedElement;
import org.rsaml.model.Processor;
import org.rsaml.model.RsamlPackage;
import org.rsaml.model.SubsumptionLink;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.DiagnosisCache;

/**
 * The Java services of the RsaML viewpoint (rsaml.odesign), called from its AQL expressions:
 * labels that speak as the tree editor does, and RsaML's findings for the validation rules.
 */
public class RsamlServices {

    /**
     * A diagram label: name and timing ("resourceChecker — real-time, 2.5 ms"); a connection shows its data, an
     * action (listed in its module) its function first ("f0_m01 › a0_f0_m01 — ..."), a processor its policy, core and
     * host when it names one.
     */
    public String rsamlLabel(EObject self) {
        if (self instanceof Action action && action.getFunction() != null) {
            return RsamlLabels.name(action.getFunction()) + " \u203a " + RsamlLabels.describe(action);
        }
        if (self instanceof Processor processor) {
            return RsamlLabels.name(processor) + " \u2014 " + (processor.isSetSchedPolicy() ? processor.getSchedPolicy().getLiteral() : "fixed priorities")
                    + (processor.getCore() >= 0 ? ", core " + processor.getCore() : ", any core")
                    + (RsamlLabels.host(processor).isEmpty() ? "" : ", on " + RsamlLabels.host(processor));
        }
        if (self instanceof Connection connection) {
            return connection.getSource() == null ? "" : RsamlLabels.dataType(connection.getSource());
        }
        if (self instanceof SubsumptionLink link && link.getDuration() > 0) {
            return RsamlLabels.name(link) + ", " + RsamlLabels.duration(link.getDuration(), link);
        }
        return RsamlLabels.describe(self);
    }

    /**
     * A name for a new element of {@code container} that no element directly in it has (RSA-09 compares
     * the names of elements of the same kind in the same container): {@code base} itself when free, else
     * {@code base2}, {@code base3}, ...
     */
    public String rsamlFreshName(EObject container, String base) {
        Set<String> taken = new HashSet<>();
        for (EObject child : container.eContents()) {
            if (child instanceof NamedElement named && named.getName() != null) {
                taken.add(named.getName().trim());
            }
        }
        String name = base;
        for (int n = 2; taken.contains(name); n++) {
            name = base + n;
        }
        return name;
    }

    /** The mission an element (a goal, a sub-goal at any depth) belongs to, or null outside a mission. */
    public EObject rsamlMission(EObject self) {
        EObject e = self;
        while (e != null && !(e instanceof Mission)) {
            e = e.eContainer();
        }
        return e;
    }

    /** The lowest CPU core no processor of the architecture claims: a new processor then shares no CPU with another. */
    public int rsamlFreeCore(EObject architecture) {
        Set<Integer> claimed = new HashSet<>();
        if (architecture instanceof Architecture a) {
            for (Processor p : a.getProcessors()) {
                claimed.add(p.getCore());
            }
        }
        int core = 0;
        while (claimed.contains(core)) {
            core++;
        }
        return core;
    }

    /**
     * The classes whose elements the RsaML diagrams draw (the domain classes of rsaml.odesign's mappings).
     * The findings of anything else (devices, orders, databases, latency requirements)
     * are shown on the nearest drawn element that contains it, so that the diagrams show every finding.
     */
    private static final Set<EClass> DRAWN = Set.of(RsamlPackage.Literals.ARCHITECTURE, RsamlPackage.Literals.LAYER,
            RsamlPackage.Literals.MODULE, RsamlPackage.Literals.FUNCTION, RsamlPackage.Literals.ACTION, RsamlPackage.Literals.RT_ACTION,
            RsamlPackage.Literals.PROCESSOR, RsamlPackage.Literals.ENTRY_PORT,
            RsamlPackage.Literals.OUTPUT_PORT, RsamlPackage.Literals.CONNECTION, RsamlPackage.Literals.INHIBITOR,
            RsamlPackage.Literals.SUPPRESSOR, RsamlPackage.Literals.MISSION, RsamlPackage.Literals.GOAL,
            RsamlPackage.Literals.PLAN, RsamlPackage.Literals.ACTIVITY, RsamlPackage.Literals.SUPERVISOR);

    /** The element whose decorations show the findings on {@code element}: itself when drawn, else its nearest drawn container. */
    public static EObject shownOn(EObject element) {
        EObject e = element;
        while (e != null && !DRAWN.contains(e.eClass())) {
            e = e.eContainer();
        }
        return e == null ? element : e;
    }

    /** The errors RsaML's rules find on this element, and on what it contains that no diagram draws, one per line ("RSA-08: ..."); empty when none. */
    public String rsamlErrors(EObject self) {
        return findings(self, Diagnostic.ERROR);
    }

    /** The warnings RsaML's rules find on this element, and on what it contains that no diagram draws, one per line; empty when none. */
    public String rsamlWarnings(EObject self) {
        return findings(self, Diagnostic.WARNING);
    }

    /** The findings shown on the element (those on drawn elements it contains are shown on them), validated once per model change. */
    private static String findings(EObject self, int severity) {
        List<EObject> shown = new ArrayList<>();
        shown.add(self);
        for (TreeIterator<EObject> i = self.eAllContents(); i.hasNext();) {
            EObject e = i.next();
            if (shownOn(e) == self) {
                shown.add(e);
            } else if (DRAWN.contains(e.eClass())) {
                i.prune();
            }
        }
        return shown.stream().flatMap(e -> DiagnosisCache.on(e).stream())
                .filter(d -> d.getSeverity() == severity)
                .map(Diagnostic::getMessage)
                .collect(Collectors.joining("\n"));
    }
}
