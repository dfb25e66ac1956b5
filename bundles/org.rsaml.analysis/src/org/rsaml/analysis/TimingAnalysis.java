/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalLong;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.rsaml.analysis.internal.Latencies;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.Reaction;
import org.rsaml.analysis.plan.PlannedAction;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.Release;
import org.rsaml.analysis.plan.UnplannableException;
import org.rsaml.model.Architecture;
import org.rsaml.model.Module;
import org.rsaml.model.Processor;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.model.support.RsamlTimes;

/**
 * The timing of an architecture, with the tasks taken from the generator's {@link ExecutionPlan}, so
 * that the analysis and the generated runtime tell the same story (docs/timing.md):
 * <ul>
 * <li>every timed release is a periodic task: its period, deadline = delay (the period when none),
 * cost = execution duration, priority = the rank the runtime gives its thread;</li>
 * <li>the releases and the reaction of one module share the module's lock, so they form one lock group
 * (the lock inherits priority on both runtimes; the analysis does not count that, an upper bound);</li>
 * <li>a sporadic module's reaction is a sporadic task at priority 0, below every real-time rank (it
 * runs on the module's worker thread, at the lowest real-time priority); an aperiodic reaction has
 * no bound on its arrivals and is excluded, said so (its worker runs at the default priority, below every
 * real-time thread), and the work at its level and its own module's releases are not analysed.</li>
 * </ul>
 */
public final class TimingAnalysis {

    /** The name of the processor of the modules that no processor names. */
    public static final String DEFAULT_PROCESSOR = "default";

    private TimingAnalysis() {
    }

    /**
     * @throws UnplannableException a time of the model cannot be represented (see {@link ExecutionPlan#of})
     * @throws TimingModelException the deployment is contradictory (a module on two processors)
     */
    public static ArchitectureTiming analyse(Architecture architecture) throws UnplannableException, TimingModelException {
        return analyse(architecture, true);
    }

    /**
     * The analysis for its verdicts only: each latency requirement's worst path, without the list of its paths
     * ({@link LatencyResult#pathBounds()} empty), which only the reports show (validation's rules need the verdict).
     *
     * @throws UnplannableException a time of the model cannot be represented (see {@link ExecutionPlan#of})
     * @throws TimingModelException the deployment is contradictory (a module on two processors)
     */
    public static ArchitectureTiming verdicts(Architecture architecture) throws UnplannableException, TimingModelException {
        return analyse(architecture, false);
    }

    private static ArchitectureTiming analyse(Architecture architecture, boolean listPaths) throws UnplannableException, TimingModelException {
        // Without latency requirements nothing reads the flows: the plan's releases and reactions suffice.
        ExecutionPlan plan = architecture.getLatencyRequirements().isEmpty() ? ExecutionPlan.releasesOf(architecture)
                : ExecutionPlan.of(architecture);
        Map<Module, Processor> allocation = allocation(architecture);
        Map<String, Group> groups = new LinkedHashMap<>();
        for (Processor p : architecture.getProcessors()) {
            groups.put(RsamlLabels.name(p), new Group(RsamlLabels.name(p), p));
        }
        List<Exclusion> excluded = new ArrayList<>();
        for (PlannedModule m : plan.modules()) {
            Processor p = allocation.get(m.module());
            String name = p == null ? DEFAULT_PROCESSOR : RsamlLabels.name(p);
            Group g = groups.computeIfAbsent(name, n -> new Group(n, null));
            g.modules++;
            for (Release r : m.releases()) {
                // SCHED_RR threads share time slices with their equals; SCHED_FIFO ones run to completion
                g.add(release(r), r.policy() != org.rsaml.model.SchedulingPolicy.RR);
            }
            if (m.reactive()) {
                if (m.minIntervalNs() > 0) {
                    g.add(reaction(m), false);
                } else {
                    String reason = "reacts to every arrival of data and the model bounds neither how often data arrives nor"
                            + " (as sporadic) how often it reacts: give it execType sporadic with a period (its minimum"
                            + " inter-arrival time) to have it analysed";
                    Exclusion x = new Exclusion(m.module(), m.qualifiedName(), name, reason);
                    excluded.add(x);
                    g.aperiodic.add(x);
                }
            }
        }
        Map<Group, String> shared = sharedCpus(groups.values());
        List<ProcessorTiming> processors = new ArrayList<>();
        for (Group g : groups.values()) {
            if (g.element == null && g.tasks.isEmpty() && g.aperiodic.isEmpty() && !architecture.getProcessors().isEmpty()) {
                continue;
            }
            ProcessorTiming p = g.analyse(plan);
            String why = shared.get(g);
            String what = "the processor shares its CPUs";
            if (why == null) {
                why = notByDeadline(g, groups.values());
                what = "the processor is not scheduled by deadline";
            }
            processors.add(why == null ? p : new ProcessorTiming(p.name(), p.element(), sharing(p.result(), why, what), p.sources(), p.notes()));
        }
        List<LatencyResult> latencies = Latencies.analyse(plan, architecture.getLatencyRequirements(), processors, listPaths);
        return new ArchitectureTiming(RsamlLabels.name(architecture), processors, excluded, latencies);
    }

    private static Map<Module, Processor> allocation(Architecture architecture) throws TimingModelException {
        int allocated = 0;
        for (Processor p : architecture.getProcessors()) {
            allocated += p.getModules().size();
        }
        Map<Module, Processor> allocation = new IdentityHashMap<>(allocated);
        for (Processor p : architecture.getProcessors()) {
            for (Module m : p.getModules()) {
                Processor other = allocation.putIfAbsent(m, p);
                if (other != null && other != p) {
                    throw new TimingModelException(p, "module " + (m.getLayer() == null ? "" : RsamlLabels.name(m.getLayer()) + "/") + RsamlLabels.name(m) + " is allocated to two processors, '"
                            + RsamlLabels.name(other) + "' and '" + RsamlLabels.name(p) + "': remove it from one of them");
                }
            }
        }
        return allocation;
    }

    /**
     * Each processor is analysed as if it had a CPU to itself. The runtime pins the threads of a
     * processor with a core to that core and confines those of every processor without one (and of
     * the modules no processor names) to the cores no processor claims: domains with modules that
     * end up on the same CPUs of one host (two without a core, or two claiming one core) interfere,
     * and no verdict of theirs holds. Processors on different hosts share nothing. Per such domain, why.
     */
    private static Map<Group, String> sharedCpus(java.util.Collection<Group> groups) {
        Map<String, Map<Integer, List<Group>>> byHost = new java.util.TreeMap<>();
        for (Group g : groups) {
            if (g.modules > 0) {
                int core = g.element == null || g.element.getCore() < 0 ? -1 : g.element.getCore();
                byHost.computeIfAbsent(RsamlLabels.host(g.element), h -> new java.util.TreeMap<>()).computeIfAbsent(core, c -> new ArrayList<>()).add(g);
            }
        }
        Map<Group, String> shared = new IdentityHashMap<>();
        byHost.values().forEach(byCore -> byCore.forEach((core, domains) -> {
            if (domains.size() < 2) {
                return;
            }
            String names = names(domains.stream().map(g -> g.name).toList());
            String why = core < 0
                    ? "processors " + names + " have no core of their own, so the runtime runs their threads on the same CPUs"
                            + " (those no processor claims) and each delays the others, which the analysis of a processor"
                            + " alone does not count: give each processor a core of its own"
                            + (domains.stream().anyMatch(g -> g.element == null)
                                    ? " (and allocate the modules no processor names to a processor)" : "")
                    : "processors " + names + " claim the same core " + core + ", so their threads share it and each delays"
                            + " the others, which the analysis of a processor alone does not count: give each processor a core"
                            + " of its own";
            domains.forEach(g -> shared.put(g, why));
        }));
        return shared;
    }

    /**
     * Why an EDF processor without a core is not scheduled by deadline where it runs, or null: beside processors with cores
     * on its host, both runtimes keep its threads to the CPUs no processor claims (docs/timing.md, "EDF beside processors
     * with cores"), where Linux, its deadline admission control on as by default, refuses SCHED_DEADLINE (it admits a
     * deadline thread only on every CPU of its root domain), so they run under SCHED_FIFO at one rank, which its analysis
     * by processor demand does not describe.
     */
    private static String notByDeadline(Group g, java.util.Collection<Group> groups) {
        if (g.element == null || g.element.getCore() >= 0 || g.modules == 0 || policy(g.element) != SchedulingPolicy.EDF) {
            return null;
        }
        List<String> cored = groups.stream().filter(o -> o.modules > 0 && o.element != null && o.element.getCore() >= 0
                && RsamlLabels.host(o.element).equals(RsamlLabels.host(g.element))).map(o -> o.name).toList();
        if (cored.isEmpty()) {
            return null;
        }
        return "EDF processor '" + g.name + "' has no core of its own beside " + (cored.size() == 1 ? "processor " : "processors ")
                + (cored.size() == 1 ? "'" + cored.get(0) + "'" : names(cored)) + " with " + (cored.size() == 1 ? "a core" : "cores")
                + ", so both runtimes keep its releases to the CPUs no processor claims, where Linux (its deadline admission"
                + " control on, as by default: sched_rt_runtime_us not -1) refuses them SCHED_DEADLINE, and they run under"
                + " SCHED_FIFO at one rank, first in first out, not by deadline (the trace says 'instead of EDF'): give its"
                + " functions fixed priorities (RM, DM), or put it on a host of its own";
    }

    private static String names(List<String> names) {
        List<String> quoted = names.stream().map(n -> "'" + n + "'").toList();
        return String.join(", ", quoted.subList(0, quoted.size() - 1)) + " and " + quoted.get(quoted.size() - 1);
    }

    /**
     * No verdict holds for a processor whose CPUs other processors' threads share, or that is not scheduled as analysed:
     * each task says why, and each sufficient bound says it does not apply ({@code what}).
     */
    private static ProcessorResult sharing(ProcessorResult r, String why, String what) {
        List<TaskResult> tasks = new ArrayList<>();
        for (TaskResult t : r.tasks()) {
            tasks.add(new TaskResult(t.task(), OptionalLong.empty(), Verdict.NOT_ANALYSED, "not analysed: " + why, null));
        }
        List<BoundCheck> bounds = new ArrayList<>();
        for (BoundCheck b : r.bounds()) {
            bounds.add(b.sufficient() && b.applicable()
                    ? new BoundCheck(b.name(), true, b.limit(), false, false, "not applicable: " + what)
                    : b);
        }
        return new ProcessorResult(r.processor(), r.policy(), tasks, r.utilisation(), bounds,
                tasks.isEmpty() ? r.verdict() : Verdict.NOT_ANALYSED, "not analysed: " + why, null);
    }

    private static TaskSource release(Release r) {
        long cost = r.costNs();
        String note = "";
        if (r.function() != null && r.action() == null) {
            long offset = 0;
            for (PlannedAction a : r.function().inlineActions()) {
                offset = Math.max(offset, a.offsetNs());
            }
            if (offset > 0) {
                // the release sleeps until each action's start date: counted as execution (sound, pessimistic)
                cost = Math.addExact(cost, offset);
                note = "its actions' start dates (up to " + RsamlTimes.text(offset)
                        + ") are counted as execution";
            }
        }
        if (r.costNs() == 0) {
            note = join(note, "the model gives no execution duration: counted as 0");
        }
        EObject element = switch (r.kind()) {
            case FUNCTION -> r.function().function();
            case ACTION -> r.action().action();
            case MODULE -> r.module().module();
        };
        Task t = new Task(r.label(), r.periodNs(), r.deadlineNs(), cost, r.rank(), 0, r.module().qualifiedName());
        return new TaskSource(t, element, r.kind().name().toLowerCase(java.util.Locale.ROOT), note);
    }

    private static TaskSource reaction(PlannedModule m) {
        Reaction r = m.reaction();
        String note = r.costFromFunctions() ? "the module gives no execution duration: the sum of its functions' is used" : "";
        Task t = new Task(r.label(), m.minIntervalNs(), r.deadlineNs(), r.costNs(), 0, 0, m.qualifiedName());
        return new TaskSource(t, m.module(), "reaction", note);
    }

    private static String join(String a, String b) {
        return a.isEmpty() ? b : a + "; " + b;
    }

    /** The analysis policy for a processor. */
    static SchedulingPolicy policy(Processor p) {
        if (p == null || !p.isSetSchedPolicy()) {
            return SchedulingPolicy.FIXED_PRIORITY;
        }
        return switch (p.getSchedPolicy()) {
            case EDF -> SchedulingPolicy.EDF;
            case LLF -> SchedulingPolicy.LLF;
            case SJF -> SchedulingPolicy.SJF;
            case OTHER -> SchedulingPolicy.OTHER;
            default -> SchedulingPolicy.FIXED_PRIORITY; // FIFO, RR, RM, DM: the runtime's ranks
        };
    }

    private static final class Group {
        final String name;
        final Processor element;
        final List<TaskSource> tasks = new ArrayList<>();
        final List<Exclusion> aperiodic = new ArrayList<>();
        final Set<String> names = new HashSet<>();
        final Set<String> runToCompletion = new HashSet<>();
        int modules;

        Group(String name, Processor element) {
            this.name = name;
            this.element = element;
        }

        /** @param fifo whether its thread runs first in, first out among equal priorities (SCHED_FIFO) */
        void add(TaskSource s, boolean fifo) {
            Task t = s.task();
            String unique = t.name();
            for (int i = 2; !names.add(unique); i++) {
                unique = t.name() + " (" + i + ")";
            }
            if (!unique.equals(t.name())) {
                t = new Task(unique, t.period(), t.deadline(), t.cost(), t.priority(), t.jitter(), t.group());
                s = new TaskSource(t, s.element(), s.kind(), s.note());
            }
            tasks.add(s);
            if (fifo) {
                runToCompletion.add(unique);
            }
        }

        ProcessorTiming analyse(ExecutionPlan plan) {
            SchedulingPolicy policy = policy(element);
            List<Task> list = tasks.stream().map(TaskSource::task).toList();
            ProcessorResult r = SchedulabilityAnalysis.analyse(name, policy, list, runToCompletion);
            List<String> notes = new ArrayList<>();
            if (policy == SchedulingPolicy.FIXED_PRIORITY) {
                notes.add("scheduled as the generated runtime does: one real-time thread per timed release at its rank"
                        + " (SCHED_FIFO, SCHED_RR for round robin), reactions on worker threads at the lowest real-time priority below them;"
                        + " the verdict holds when the program runs with real-time priorities (not with --no-realtime)");
            } else if (policy == SchedulingPolicy.EDF) {
                notes.add("scheduled by deadline: the generated C++ runtime runs each timed release under SCHED_DEADLINE"
                        + " (runtime = its execution duration, its deadline and period, reclaiming bandwidth no deadline thread"
                        + " reserved) where the kernel permits it, and its trace says when not; each release thread becomes a"
                        + " deadline thread at its first release and ends every job by yielding the rest of its runtime, so the"
                        + " kernel's periods are its releases, and there the verdict is claimed for the program granted that,"
                        + " within the limits docs/timing.md (EDF) states: what was measured, on how many CPUs, and a clock that"
                        + " a time service slews. The ROS 2 nodes do the same on each release's own executor thread: at its"
                        + " timer's first call the thread becomes a deadline thread and runs the release's jobs from there, every"
                        + " job ending by yielding, without waiting for the timer again; there the verdict is claimed as on the"
                        + " C++ runtime, deadlines shorter than periods included (docs/timing.md, EDF)");
                if (element != null && element.getCore() >= 0) {
                    notes.add("core " + element.getCore() + " does not hold EDF: Linux admits a SCHED_DEADLINE thread only on every CPU of its"
                            + " root domain (its deadline admission control on, as by default), so the C++ runtime runs this processor's releases on every core of the machine (not core "
                            + element.getCore() + " alone, and ahead of every other processor's threads there), and on ROS 2, whose launch"
                            + " pins the processor's container to core " + element.getCore() + " (taskset), the kernel refuses SCHED_DEADLINE"
                            + " and they run under SCHED_FIFO at their ranks (the trace says 'instead of EDF'): on neither runtime does this"
                            + " processor run as analysed, unless the machine gives core " + element.getCore() + " a root domain of its own"
                            + " (an exclusive cpuset partition)");
                }
            } else {
                notes.add("the processor is declared " + element.getSchedPolicy().getLiteral() + ": the verdict is for a platform"
                        + " scheduling it so, while the generated C++ runtime schedules by fixed priorities");
            }
            notes.add("every task released together (start dates and offsets ignored): the worst case");
            if (!aperiodic.isEmpty()) {
                r = withoutLevelZero(r, policy, aperiodic);
                notes.add("aperiodic reactions (" + String.join(", ", aperiodic.stream().map(Exclusion::label).toList())
                        + ") share this processor below the real-time ranks; their load is unbounded");
            }
            return new ProcessorTiming(name, element, r, tasks, notes);
        }
    }

    /**
     * The tasks that aperiodic work can delay without bound lose their verdict: under fixed priorities
     * those analysed at priority 0 (reactions, and releases sharing a lock with one, the module's own
     * aperiodic reaction included: it holds the module's lock at priority 0, where aperiodic work can
     * keep it from running); under any other policy all of them. A proven miss stays a miss.
     */
    private static ProcessorResult withoutLevelZero(ProcessorResult r, SchedulingPolicy policy, List<Exclusion> aperiodic) {
        String who = String.join(", ", aperiodic.stream().map(Exclusion::label).toList());
        // the lock groups of the modules whose reaction is aperiodic: a module's tasks are grouped by its qualified name
        Set<String> lockedWith = new HashSet<>(aperiodic.stream().map(Exclusion::label).toList());
        List<TaskResult> tasks = new ArrayList<>();
        Verdict verdict = Verdict.MEETS;
        int[] effective = org.rsaml.analysis.internal.ResponseTimes.effectivePriorities(r.tasks().stream().map(TaskResult::task).toList());
        for (int i = 0; i < r.tasks().size(); i++) {
            TaskResult t = r.tasks().get(i);
            boolean locked = lockedWith.contains(t.task().group());
            boolean exposed = policy != SchedulingPolicy.FIXED_PRIORITY || effective[i] <= 0 || locked;
            if (exposed && t.verdict() == Verdict.MEETS) {
                t = new TaskResult(t.task(), OptionalLong.empty(), Verdict.NOT_ANALYSED, locked
                        ? "not analysed: it waits for its module's lock while the module's aperiodic reaction, which the analysis"
                                + " excludes, holds it, and no such wait is counted (aperiodic reactions on this processor: " + who + ")"
                        : "not analysed: aperiodic reactions on this processor (" + who + ") can delay it without bound", null);
            }
            verdict = verdict.and(t.verdict());
            tasks.add(t);
        }
        String explanation = verdict == r.verdict() ? r.explanation()
                : r.explanation() + "; but aperiodic reactions (" + who + ") can delay the work below the real-time ranks";
        return new ProcessorResult(r.processor(), r.policy(), tasks, r.utilisation(), r.bounds(), verdict, explanation, r.demand());
    }
}
