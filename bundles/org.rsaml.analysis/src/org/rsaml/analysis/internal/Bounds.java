/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.internal;

import java.math.BigInteger;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.rsaml.analysis.BoundCheck;
import org.rsaml.analysis.Rational;
import org.rsaml.analysis.SchedulingPolicy;
import org.rsaml.analysis.Task;

/** Utilisation bounds: quick, but only sufficient (or only necessary), and stated as such. */
public final class Bounds {

    /** Above this many tasks the bounds are compared in floating point, with a safety margin. */
    private static final int EXACT_LIMIT = 64;
    private static final double MARGIN = 1e-12;

    /** Beyond this distance from a bound, a sum in floating point of at most {@link #EXACT_LIMIT} terms is on the side it says. */
    private static final double DECIDED = 1e-9;

    /**
     * Liu and Layland's bound as the result writes it, for the common numbers of tasks, each made when first asked for
     * (formatting all of them up front cost every start of a validation some milliseconds).
     */
    private static final String[] LIMITS = new String[EXACT_LIMIT + 1];

    private Bounds() {
    }

    private static String limit(double ll) {
        return String.format(Locale.ROOT, "U <= %.4f", ll);
    }

    /** {@link #limit(double)} of {@code ll}, Liu and Layland's bound for {@code n} tasks, kept for the common {@code n}. */
    private static String limit(int n, double ll) {
        if (n >= LIMITS.length) {
            return limit(ll);
        }
        String text = LIMITS[n];
        if (text == null) {
            // Threads that race here make the same text; a String is safe to share without a lock.
            text = limit(ll);
            LIMITS[n] = text;
        }
        return text;
    }

    private static double logProduct(List<Task> tasks) {
        double logProduct = 0;
        for (Task t : tasks) {
            logProduct += Math.log1p((double) t.cost() / t.period());
        }
        return logProduct;
    }

    public static List<BoundCheck> check(SchedulingPolicy policy, List<Task> tasks, Utilisation utilisation) {
        List<BoundCheck> checks = new ArrayList<>();
        checks.add(new BoundCheck("utilisation", false, "U <= 1", true, utilisation.versusOne() <= 0,
                "necessary under any scheduler"));
        if (policy != SchedulingPolicy.FIXED_PRIORITY || tasks.isEmpty()) {
            return checks;
        }
        String why = rateMonotonicImplicit(tasks);
        int n = tasks.size();
        double ll = n * (Math.pow(2, 1.0 / n) - 1);
        String llLimit = limit(n, ll);
        if (why != null) {
            checks.add(new BoundCheck("Liu & Layland", true, llLimit, false, false, why));
            checks.add(new BoundCheck("hyperbolic", true, "prod(U_i + 1) <= 2", false, false, why));
            return checks;
        }
        boolean llHolds;
        boolean hypHolds;
        String how;
        if (n <= EXACT_LIMIT) {
            // exact: decided in floating point where the sum is clearly on one side (its error is below 1e-13 for
            // 64 tasks), else by integers: U <= n (2^(1/n) - 1)  <=>  (p + n q)^n <= 2 (n q)^n  with U = p / q
            double logProduct = logProduct(tasks);
            if (Math.abs(utilisation.value - ll) > DECIDED) {
                llHolds = utilisation.value < ll;
            } else {
                Rational u = utilisation.exact();
                BigInteger p = u.numerator();
                BigInteger nq = u.denominator().multiply(BigInteger.valueOf(n));
                llHolds = p.add(nq).pow(n).compareTo(nq.pow(n).shiftLeft(1)) <= 0;
            }
            if (Math.abs(logProduct - Math.log(2)) > DECIDED) {
                hypHolds = logProduct < Math.log(2);
            } else {
                BigInteger product = BigInteger.ONE;
                BigInteger periods = BigInteger.ONE;
                for (Task t : tasks) {
                    product = product.multiply(BigInteger.valueOf(t.cost()).add(BigInteger.valueOf(t.period())));
                    periods = periods.multiply(BigInteger.valueOf(t.period()));
                }
                hypHolds = product.compareTo(periods.shiftLeft(1)) <= 0;
            }
            how = "exact";
        } else {
            double logProduct = logProduct(tasks);
            llHolds = utilisation.value <= ll - MARGIN;
            hypHolds = logProduct <= Math.log(2) - MARGIN;
            how = "floating point with a margin of " + MARGIN + " (more than " + EXACT_LIMIT + " tasks)";
        }
        checks.add(new BoundCheck("Liu & Layland", true, llLimit, true, llHolds,
                "sufficient for rate-monotonic priorities and deadlines equal to periods; " + how));
        checks.add(new BoundCheck("hyperbolic", true, "prod(U_i + 1) <= 2", true, hypHolds,
                "sufficient for rate-monotonic priorities and deadlines equal to periods (Bini, Buttazzo & Buttazzo 2003); " + how));
        return checks;
    }

    /** Why the bounds do not apply when a task can wait for a lower-priority task holding their module's lock; else null. */
    private static String blocking(List<Task> tasks) {
        java.util.Map<String, Task> lowest = new java.util.HashMap<>();
        for (Task t : tasks) {
            if (t.group() != null) {
                lowest.merge(t.group(), t, (a, b) -> b.priority() < a.priority() ? b : a);
            }
        }
        for (Task t : tasks) {
            Task u = t.group() == null ? null : lowest.get(t.group());
            if (u != null && u.priority() < t.priority()) {
                return "not applicable: task '" + t.name() + "' shares its module's lock with the lower-priority '" + u.name()
                        + "' and can wait for it, and the bound assumes independent tasks";
            }
        }
        return null;
    }

    /** Null when the tasks have deadlines equal to their periods, no jitter and rate-monotonic priorities; else why not. */
    private static String rateMonotonicImplicit(List<Task> tasks) {
        String blocking = blocking(tasks);
        if (blocking != null) {
            return blocking;
        }
        for (Task t : tasks) {
            if (t.deadline() != t.period()) {
                return "not applicable: task '" + t.name() + "' has a deadline other than its period";
            }
            if (t.jitter() != 0) {
                return "not applicable: task '" + t.name() + "' has release jitter";
            }
        }
        // by period; every task must have a higher priority than all tasks of longer periods
        List<Task> sorted = new ArrayList<>(tasks);
        sorted.sort(java.util.Comparator.comparingLong(Task::period));
        Task lowest = null; // the lowest-priority task of the shorter periods seen so far
        int i = 0;
        while (i < sorted.size()) {
            int j = i;
            while (j < sorted.size() && sorted.get(j).period() == sorted.get(i).period()) {
                Task b = sorted.get(j);
                if (lowest != null && lowest.priority() <= b.priority()) {
                    return "not applicable: priorities are not rate monotonic ('" + lowest.name()
                            + "' has the shorter period but not the higher priority than '" + b.name() + "')";
                }
                j++;
            }
            for (int k = i; k < j; k++) {
                if (lowest == null || sorted.get(k).priority() < lowest.priority()) {
                    lowest = sorted.get(k);
                }
            }
            i = j;
        }
        return null;
    }
}
