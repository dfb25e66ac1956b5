/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.rsaml.analysis.Task;
import org.rsaml.analysis.TaskResult;
import org.rsaml.analysis.Witness;

/**
 * Tasks of one priority that run first in, first out, with nothing above them and nothing below that
 * can block them (the runtime's SCHED_FIFO threads of a processor's highest rank): a job waits for
 * exactly the jobs of the level released before or with it and not yet done. A job released at t in a
 * busy period that began at s completes by s plus the work released in [s, t], at most
 * sum_j (floor((t - s)/T_j) + 1) C_j &lt;= sum_j C_j + U (t - s); with U &lt;= 1 its response is
 * therefore at most sum_j C_j, and all the tasks released together, the analysed one last among them,
 * reach it. So the worst response of every task of the level is the sum of their costs (exact), and
 * with U &gt; 1 there is no bound. Tasks with release jitter (lock groups) get {@link NonPreemptive},
 * which bounds it.
 */
public final class FirstInFirstOut {

    private FirstInFirstOut() {
    }

    /** One task of the level: the definition {@link #of(List)} is held to. */
    public static TaskResult of(List<Task> level, Task task) {
        List<Task> others = ResponseTimes.interfering(level, task);
        boolean jitter = task.jitter() > 0 || others.stream().anyMatch(t -> t.jitter() > 0);
        if (jitter) {
            return NonPreemptive.of(level, task);
        }
        if (ResponseTimes.utilisationVersusOne(task, others) > 0) {
            return ResponseTimes.overloaded(task, ResponseTimes.utilisation(task, others));
        }
        try {
            long worst = task.cost();
            for (Task t : others) {
                worst = Arith.add(worst, t.cost());
            }
            TaskResult r = MissWitnesses.result(task, worst, 0, () -> null);
            if (r.verdict() != org.rsaml.analysis.Verdict.MISSES) {
                return r;
            }
            // one job of each other task delays it: the one released with it
            List<Task> delaying = new ArrayList<>(others.stream().filter(t -> t.cost() > 0).toList());
            delaying.sort((a, b) -> Long.compare(b.cost(), a.cost()));
            Map<String, Long> listed = new LinkedHashMap<>();
            for (Task t : delaying.subList(0, Math.min(MissWitnesses.MAX_LISTED, delaying.size()))) {
                listed.put(t.name(), 1L);
            }
            Witness w = new Witness(task.name(), 0, 0, worst, List.of(), listed, null, false, delaying.size() - listed.size());
            return new TaskResult(task, r.responseTime(), r.verdict(), r::explanation, w);
        } catch (ArithmeticException e) {
            return ResponseTimes.notAnalysed(task, new Arith.TooLarge().getMessage());
        }
    }

    /**
     * {@link #of(List, Task)} of every task of the level, in its order, in time linear in the level's
     * size: the worst response (the sum of the level's costs) and the level's utilisation are the same
     * for every task, and the tasks that delay the most are one sorted list, so nothing is recomputed
     * per task (thousands of FIFO releases at a processor's top rank cost n², not n, that way).
     */
    public static TaskResult[] of(List<Task> level) {
        TaskResult[] out = new TaskResult[level.size()];
        if (level.stream().anyMatch(t -> t.jitter() > 0)) {
            for (int i = 0; i < out.length; i++) {
                out[i] = NonPreemptive.of(level, level.get(i));
            }
            return out;
        }
        if (level.isEmpty()) {
            return out;
        }
        if (ResponseTimes.utilisationVersusOne(level.get(0), level.subList(1, level.size())) > 0) {
            // the whole level's, as for each task
            double u = ResponseTimes.utilisation(level.get(0), level.subList(1, level.size()));
            for (int i = 0; i < out.length; i++) {
                out[i] = ResponseTimes.overloaded(level.get(i), u);
            }
            return out;
        }
        long sum = 0;
        try {
            for (Task t : level) {
                sum = Arith.add(sum, t.cost());
            }
        } catch (ArithmeticException e) {
            for (int i = 0; i < out.length; i++) {
                out[i] = ResponseTimes.notAnalysed(level.get(i), new Arith.TooLarge().getMessage());
            }
            return out;
        }
        // the tasks that delay the most, most first (a stable sort: ties in the level's order), one more than a witness lists
        List<Task> delaying = new ArrayList<>(level.stream().filter(t -> t.cost() > 0).toList());
        delaying.sort((a, b) -> Long.compare(b.cost(), a.cost()));
        List<Task> top = delaying.subList(0, Math.min(MissWitnesses.MAX_LISTED + 1, delaying.size()));
        for (int i = 0; i < out.length; i++) {
            Task task = level.get(i);
            TaskResult r = MissWitnesses.result(task, sum, 0, () -> null);
            if (r.verdict() != org.rsaml.analysis.Verdict.MISSES) {
                out[i] = r;
                continue;
            }
            Map<String, Long> listed = new LinkedHashMap<>();
            for (Task t : top) {
                if (t != task && listed.size() < MissWitnesses.MAX_LISTED) {
                    listed.put(t.name(), 1L);
                }
            }
            int others = delaying.size() - (task.cost() > 0 ? 1 : 0);
            Witness w = new Witness(task.name(), 0, 0, sum, List.of(), listed, null, false, others - listed.size());
            out[i] = new TaskResult(task, r.responseTime(), r.verdict(), r::explanation, w);
        }
        return out;
    }
}
