/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.lang.management.MemoryUsage;
import java.util.concurrent.atomic.AtomicLong;

/** Tells the loader to give up on a model that does not fit in the heap, before the collector thrashes. */
public final class HeapWatch {

    /** How many times this JVM's loader was told to give up. */
    private static final AtomicLong GIVEN_UP = new AtomicLong();

    private HeapWatch() {
    }

    /**
     * How many times so far, in this JVM, the loader gave up on a model as too large for the heap: a command during
     * which this grew had a result that depends on the heap's size (the resident process has it run again in a JVM of
     * its own).
     */
    public static long givenUp() {
        return GIVEN_UP.get();
    }

    /**
     * Whether the heap's long-lived part is still at least 95% full after its last collection: the
     * old generation where the collector has one (Serial, Parallel, G1, generational ZGC), the
     * whole heap where it has not (ZGC, Shenandoah). Eden and survivor spaces say nothing here:
     * after a minor collection they are routinely full (the parallel collector's survivor space
     * especially), which is how the collector works, not a sign the model does not fit.
     */
    static boolean nearlyExhausted() {
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP && pool.isCollectionUsageThresholdSupported() && !youngGeneration(pool.getName())) {
                MemoryUsage afterCollection = pool.getCollectionUsage();
                long max = pool.getUsage().getMax();
                if (afterCollection != null && max > 0 && afterCollection.getUsed() > max / 20 * 19) {
                    GIVEN_UP.incrementAndGet();
                    return true;
                }
            }
        }
        return false;
    }

    /** Pools where new objects live until a minor collection moves them on, by the names HotSpot's collectors give them. */
    private static boolean youngGeneration(String poolName) {
        return poolName.contains("Eden") || poolName.contains("Survivor") || poolName.contains("Young") || poolName.contains("Nursery");
    }
}
