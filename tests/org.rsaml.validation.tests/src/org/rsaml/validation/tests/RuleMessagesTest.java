/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.eclipse.emf.ecore.EObject;
import org.rsaml.model.RsamlFactory;
import org.rsaml.tests.support.TestRepository;
import org.rsaml.validation.RsamlModelValidator;
import org.rsaml.validation.internal.MessageParameters;
import org.rsaml.validation.internal.TimingChecks;

/** The messages of the rules a user meets on new kinds of models say what to change and name the limit. */
class RuleMessagesTest {

    private static List<String> messages(String fixture, String ruleId) throws Exception {
        return RsamlModelValidator.validate(TestRepository.resource("org.rsaml.validation.tests", "rules").resolve(fixture)).stream()
                .filter(f -> f.ruleId().equals(ruleId)).map(f -> f.qualifiedName() + ": " + f.message())
                .collect(Collectors.toList());
    }

    private static List<String> sorted(List<String> list) {
        return list.stream().sorted().collect(Collectors.toList());
    }

    /**
     * Every name a template may use ({@code MessageParameters.names()}, which the catalogue's check reads) has a value
     * computed for it, or is one the timing analysis supplies: the names are listed once for the check and once in the
     * computation, and a name in the list alone would fail only when its rule fired.
     */
    @Test
    void everyMessageParameterATemplateMayNameIsComputed() {
        EObject element = RsamlFactory.eINSTANCE.createArchitecture();
        List<String> unknown = new ArrayList<>();
        for (String name : MessageParameters.names()) {
            try {
                MessageParameters.render("{" + name + "}", element);
            } catch (IllegalArgumentException e) {
                if (String.valueOf(e.getMessage()).contains("unknown message parameter")) {
                    unknown.add(name);
                }
            } catch (RuntimeException e) {
                // computed, but not for an architecture (a cast or a missing reference): the name is known
            }
        }
        assertEquals(List.of(), unknown, "names a template may use that have no value computed for them");
        assertTrue(MessageParameters.names().containsAll(TimingChecks.PARAMETERS), "the timing analysis' parameters are names too");
    }

    @Test
    void aModuleThatNothingActivatesIsToldWhatNeverHappensAndToGetAPeriodOrAnInputThatRuns() throws Exception {
        String add = "; add a period (execType periodic and a period above 0) or an input from a module that runs (a connection"
                + " to one of its entry ports from an output port of a periodic module, or of a module such a module feeds)";
        String never = " is never activated: it is not periodic, has no periodic function or action, and ";
        assertEquals(List.of(
                "robot/behaviour/wander: Module 'wander'" + never + "has no entry port, so its outputs 'heading' never carry more"
                        + " than their initial values" + add,
                "robot/behaviour/integrate: Module 'integrate'" + never + "none of its entry ports receives data, so its outputs"
                        + " 'pose' never carry more than their initial values" + add,
                "robot/behaviour/source: Module 'source'" + never + "has no entry port, so its outputs 'out' never carry more"
                        + " than their initial values and its functions 'sample' never run" + add,
                // connected, but only to a module that never runs: its initial value starts no reaction
                "robot/behaviour/relay: Module 'relay'" + never + "its entry ports receive data only from modules that are never"
                        + " activated either ('source'), so its outputs 'out' never carry more than their initial values and its"
                        + " functions 'forward' never run" + add,
                // no output port, but an actuator and a function that nothing ever runs
                "robot/behaviour/driver: Module 'driver'" + never + "has no entry port, so its actuators 'motor' are never driven"
                        + " and its functions 'drive' never run" + add,
                // a cycle with nothing timed: each waits for the other
                "robot/behaviour/ping: Module 'ping'" + never + "its entry ports receive data only from modules that are never"
                        + " activated either ('pong'), so its outputs 'out' never carry more than their initial values and its"
                        + " functions 'answer' never run" + add,
                "robot/behaviour/pong: Module 'pong'" + never + "its entry ports receive data only from modules that are never"
                        + " activated either ('ping'), so its outputs 'out' never carry more than their initial values and its"
                        + " functions 'answer' never run" + add),
                messages("rule-RSA-19-violated.rsaml", "RSA-19"), "RSA-19 names each module nothing activates, says what of it never happens and how to make it run");
    }

    @Test
    void aLinkThatNeverLapsesNamesTheTriggersPeriodAndTheDuration() throws Exception {
        assertEquals(sorted(List.of(
                "robot/safety/monitor/stopDrive: Inhibitor 'stopDrive' of module 'monitor' stays active for 500.0 ms after each"
                        + " message on its trigger 'monitor.stop' that asserts it (a boolean trigger: every true), but module"
                        + " 'monitor' sends on it every 50.0 ms (its own period), no longer than that: while the trigger keeps"
                        + " asserting it, the inhibitor never lapses and output 'drive.cmd' sends nothing",
                "robot/safety/planner/override: Suppressor 'override' of module 'planner' stays active for 2000.0 ms after each"
                        + " message on its trigger 'planner.goal' that asserts it (a numeric trigger: every message), but module"
                        + " 'planner' sends on it every 2.0 s (the period of function 'plan'), no longer than that: while the"
                        + " trigger keeps asserting it, the suppressor never lapses and entry 'drive.goal' receives nothing from"
                        + " its own connections")),
                sorted(messages("rule-RSA-26-violated.rsaml", "RSA-26")), "RSA-26 names each link that never lapses, with its trigger's period and its duration");
    }

    @Test
    void aFunctionOrActionLongerThanItsBudgetIsReportedOnItself() throws Exception {
        assertEquals(sorted(List.of(
                "robot/deliberation/planner/plan: Function 'plan' takes 45.0 ms, longer than the 40.0 ms budget of its layer"
                        + " 'deliberation'",
                "robot/mapping/mapper/update: Function 'update' takes 50.0 s, longer than the 50.0 ms of its module 'mapper'",
                "robot/mapping/mapper/update/fuse: Action 'fuse' takes 60.0 s, longer than the 50.0 s of its function 'update'"
                        + " and the 50.0 ms of its module 'mapper'")),
                sorted(messages("rule-RSA-27-violated.rsaml", "RSA-27")), "RSA-27 reports each function or action over its budget on itself, naming the budget it exceeds");
    }

    @Test
    void aTopicNameThatRos2CannotUseSaysWhyAndNamesThePortItClashesWith() throws Exception {
        assertEquals(sorted(List.of(
                "robot/base/lidar/scan: Output port 'scan' of module 'lidar' names the topic 'scan', but entry port 'laser' of"
                        + " module 'obstacles', connected to it, names 'laser': connected ports share one topic",
                "robot/base/obstacles/laser: Entry port 'laser' of module 'obstacles' names the topic 'laser', but output port"
                        + " 'scan' of module 'lidar', connected to it, names 'scan': connected ports share one topic",
                "robot/base/odometry/pose: Output port 'pose' of module 'odometry' names the topic 'base pose', which is not a"
                        + " ROS 2 topic name",
                "robot/base/logger/diagnostics: Output port 'diagnostics' of module 'logger' names the topic '/diagnostics', as"
                        + " output port 'status' of module 'monitor' does, which it is not connected to: ROS 2 would connect them",
                "robot/base/monitor/status: Output port 'status' of module 'monitor' names the topic 'diagnostics', as output"
                        + " port 'diagnostics' of module 'logger' does, which it is not connected to: ROS 2 would connect them")),
                sorted(messages("rule-RSA-28-violated.rsaml", "RSA-28")), "RSA-28 says why each topic name cannot be used and names the port it clashes with");
    }

    @Test
    void aLayerWhosePackageNameIsUnusableSaysWhyAndNamesTheLayerItClashesWith() throws Exception {
        assertEquals(sorted(List.of(
                "robot/Drivers: Layer 'Drivers' would put its nodes in the same ROS 2 package as layer 'drivers' (the package name ending"
                        + " _drivers, packages perLayer); rename one of them",
                "robot/drivers: Layer 'drivers' would put its nodes in the same ROS 2 package as layer 'Drivers' (the package name ending"
                        + " _drivers, packages perLayer); rename one of them",
                "robot/interfaces: Layer 'interfaces' would put its nodes in the package ending _interfaces, the package of the model's"
                        + " message types (packages perLayer); rename the layer",
                "robot/\u5bfc\u822a: Layer '\u5bfc\u822a' has no ASCII letter or digit in its name to make the name of its nodes' ROS 2 package"
                        + " from (packages perLayer); a ROS package name is lower-case letters, digits and underscores: rename the layer")),
                sorted(messages("rule-RSA-29-violated.rsaml", "RSA-29")), "RSA-29 says why each layer's package name cannot be used and names the layer it clashes with");
    }

    @Test
    void timesTheGeneratedCodeCannotHoldNameTheLimit() throws Exception {
        List<String> messages = messages("rule-RSA-20-violated.rsaml", "RSA-20");
        String limit = "; times may be at most 1152921504606846976 ns (2^60, about 36.5 years) and a period above 0 at least 1 ns";
        assertEquals(sorted(List.of("robot/functional: Layer 'functional' has a time value the generated code cannot represent: "
                + "maxExecTime 1152921504.606847 s" + limit,
                "robot/functional/odometry: Module 'odometry' has a time value the generated code cannot represent: "
                        + "period 1000000000000000000000 ms" + limit,
                "robot/functional/odometry/integrate: Function 'integrate' has a time value the generated code cannot represent: "
                        + "period 0.0005 us" + limit,
                "robot/lidar: Sensor 'lidar' has a time value the generated code cannot represent: period 9467280000.0 s" + limit)),
                sorted(messages), "RSA-20 names each time value the generated code cannot hold, and the limit");
    }

    @Test
    void namesTooLongForAFileNameNameTheLimit() throws Exception {
        String limit = "; names and message types may have at most 100 characters, because generated file names are made from them"
                + " and a file name may have at most 255 bytes";
        String longName = "obstacleAvoidanceBehaviour".repeat(5).substring(0, 130);
        assertEquals(sorted(List.of("robot/functional/" + longName + ": Module '" + longName + "' has a name of 130 characters" + limit,
                "robot/functional/laser/scan: Output port 'scan' has a message type of 125 characters" + limit)),
                sorted(messages("rule-RSA-21-violated.rsaml", "RSA-21")), "RSA-21 names each name too long for a file name, its length and the limit");
    }
}
