/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.rsaml.analysis.plan.Flow;
import org.rsaml.analysis.plan.PlannedModule;

/**
 * The reactive cycles of a plan ({@link ExecutionPlan#reactiveCycles()}): the strongly connected
 * components of the graph of flows between reacting modules, by Tarjan's algorithm. Iterative, with
 * its own stack, so that a chain of any length is searched (the call stack would overflow near
 * 10,000 modules), and linear in modules and flows.
 */
final class ReactiveCycles {

    private ReactiveCycles() {
    }

    static List<List<PlannedModule>> of(ExecutionPlan plan) {
        List<PlannedModule> modules = plan.modules;
        int n = modules.size();
        Map<PlannedModule, Integer> number = new IdentityHashMap<>();
        for (int i = 0; i < n; i++) {
            number.put(modules.get(i), i);
        }
        // Adjacency in flow order (compressed rows), reacting modules only.
        int[] degree = new int[n + 1];
        List<int[]> edges = new ArrayList<>();
        for (Flow f : plan.flows) {
            if (f.source.module.reactive && f.target.module.reactive) {
                int from = number.get(f.source.module);
                edges.add(new int[] { from, number.get(f.target.module) });
                degree[from + 1]++;
            }
        }
        for (int i = 0; i < n; i++) {
            degree[i + 1] += degree[i];
        }
        int[] start = degree;
        int[] successor = new int[edges.size()];
        int[] fill = Arrays.copyOf(start, n);
        for (int[] e : edges) {
            successor[fill[e[0]]++] = e[1];
        }

        int[] index = new int[n];
        Arrays.fill(index, -1);
        int[] low = new int[n];
        boolean[] onStack = new boolean[n];
        int[] stack = new int[n];
        int stackSize = 0;
        int[] callNode = new int[n];
        int[] callEdge = new int[n];
        int next = 0;
        List<List<PlannedModule>> cycles = new ArrayList<>();

        for (int root = 0; root < n; root++) {
            if (index[root] >= 0) {
                continue;
            }
            int depth = 0;
            callNode[0] = root;
            callEdge[0] = start[root];
            index[root] = low[root] = next++;
            stack[stackSize++] = root;
            onStack[root] = true;
            while (depth >= 0) {
                int v = callNode[depth];
                if (callEdge[depth] < start[v + 1]) {
                    int w = successor[callEdge[depth]++];
                    if (index[w] < 0) {
                        index[w] = low[w] = next++;
                        stack[stackSize++] = w;
                        onStack[w] = true;
                        depth++;
                        callNode[depth] = w;
                        callEdge[depth] = start[w];
                    } else if (onStack[w]) {
                        low[v] = Math.min(low[v], index[w]);
                    }
                    continue;
                }
                // v is finished: close its component, then return to its caller.
                if (low[v] == index[v]) {
                    int from = stackSize;
                    do {
                        from--;
                        onStack[stack[from]] = false;
                    } while (stack[from] != v);
                    if (stackSize - from > 1 || selfLoop(v, start, successor)) {
                        int[] members = Arrays.copyOfRange(stack, from, stackSize);
                        Arrays.sort(members); // module order
                        List<PlannedModule> cycle = new ArrayList<>(members.length);
                        for (int m : members) {
                            cycle.add(modules.get(m));
                        }
                        cycles.add(cycle);
                    }
                    stackSize = from;
                }
                depth--;
                if (depth >= 0) {
                    int caller = callNode[depth];
                    low[caller] = Math.min(low[caller], low[v]);
                }
            }
        }
        return cycles;
    }

    private static boolean selfLoop(int v, int[] start, int[] successor) {
        for (int e = start[v]; e < start[v + 1]; e++) {
            if (successor[e] == v) {
                return true;
            }
        }
        return false;
    }
}
