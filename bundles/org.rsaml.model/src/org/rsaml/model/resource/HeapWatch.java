/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.resource;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.lang.management.MemoryUsage;

/** Tells the loader to give up on a model that does not fit in the heap, before the collector thrashes. */
final class HeapWatch {

    private HeapWatch() {
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
