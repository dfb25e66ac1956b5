/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

/**
 * How long bringing managed nodes down may take when a launch stops, in the three places that must
 * agree, from the number {@code n} of managed nodes one lifecycle manager brings down (those of one
 * container's processor):
 * <ul>
 * <li>the lifecycle manager deactivates and cleans up each node within a deadline of its own,
 * {@link #NODE_DEADLINE_MS} (its parameter {@code node_deadline_ms}), the last node first: n deadlines
 * at most;</li>
 * <li>the processes of those nodes serve them after SIGINT for {@link #graceMs} (their argument
 * {@link #GRACE_OPTION}): the manager's n deadlines and {@link #ANSWER_MS} for the last answer's way
 * back;</li>
 * <li>{@code ros2 launch} escalates to SIGTERM {@link #sigtermTimeoutS} after its SIGINT (the actions'
 * {@code sigterm_timeout}): the grace and {@link #EXIT_MS} for the process to print its summary and
 * exit on its own.</li>
 * </ul>
 * For one managed node these are 2 s, 3 s and 5 s ({@code ros2 launch}'s own default). The runtime's
 * values without the parameter and the argument (a manager or a node started by hand) are those for
 * one node (runtime/ros2/rsaml: {@code NODE_DEADLINE_WITHOUT_PARAMETER_MS}, {@code GRACE_WITHOUT_ARGUMENT_MS}).
 */
public final class Ros2Shutdown {

    /** Each managed node's deactivate and cleanup (with the question of its state), in milliseconds. */
    public static final long NODE_DEADLINE_MS = 2000;

    /** What a process waits beyond the manager's deadlines: the last cleanup's answer on its way back. */
    public static final long ANSWER_MS = 1000;

    /** What {@code ros2 launch} waits beyond a process's grace before SIGTERM: its summary and its exit. */
    public static final long EXIT_MS = 2000;

    /** The option of a process's command line that gives it its grace (runtime/ros2/rsaml/scheduling.hpp: GRACE_OPTION). */
    public static final String GRACE_OPTION = "--rsaml-shutdown-grace-ms";

    private Ros2Shutdown() {
    }

    /** How long a process serves its managed nodes after SIGINT when their manager brings down {@code managed} nodes. */
    public static long graceMs(int managed) {
        return Math.max(1, managed) * NODE_DEADLINE_MS + ANSWER_MS;
    }

    /** How long {@code ros2 launch} waits after SIGINT before SIGTERM, in seconds, for the processes of such a manager. */
    public static String sigtermTimeoutS(int managed) {
        long ms = graceMs(managed) + EXIT_MS;
        return ms % 1000 == 0 ? Long.toString(ms / 1000) : Double.toString(ms / 1000.0);
    }
}
