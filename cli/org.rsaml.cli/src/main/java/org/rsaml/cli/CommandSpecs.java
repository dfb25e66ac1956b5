/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.util.List;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;
import picocli.CommandLine.Model.UsageMessageSpec;

/**
 * picocli's model of a command, built by code: every option is defined once, in its command's class, with picocli's
 * builders. picocli reading annotations instead makes the JVM generate a proxy class per annotation type on every run,
 * classes no class data holds (docs/benchmarks.md, start-up).
 */
final class CommandSpecs {

    private CommandSpecs() {
    }

    /** A command of {@code rsaml} named {@code name}, run by {@code command}. */
    static CommandSpec command(String name, Object command, String... description) {
        CommandSpec spec = CommandSpec.wrapWithoutInspection(command);
        spec.name(name);
        spec.usageMessage().description(description);
        return spec;
    }

    /** The exit codes help lists, each {@code "code:meaning"}. */
    /** The exit codes of a validation, as {@code rsaml --help} and {@code rsaml validate --help} list them. */
    static final String[] VALIDATION_EXIT_CODES = {"0:clean: no finding at or above --fail-on",
            "1:findings at or above --fail-on",
            "2:usage error, or an input that could not be read"};

    static void exitCodes(CommandSpec spec, String... codes) {
        spec.usageMessage().exitCodeListHeading("%nExit codes:%n").exitCodeList(UsageMessageSpec.keyValuesMap(codes));
    }

    /** {@code -h, --help} and {@code -V, --version}, added after the command's own options (help lists them so). */
    static void standardHelpOptions(CommandSpec spec) {
        CommandSpec mixin = CommandSpec.create();
        mixin.addOption(OptionSpec.builder("-h", "--help").usageHelp(true).type(boolean.class)
                .description("Show this help message and exit.").build());
        mixin.addOption(OptionSpec.builder("-V", "--version").versionHelp(true).type(boolean.class)
                .description("Print version information and exit.").build());
        // picocli's own name for these two, so that its model says the command has the standard help options.
        spec.addMixin("mixinStandardHelpOptions", mixin);
    }

    /** An option taking a value of {@code type}, shown as {@code label}. */
    static OptionSpec.Builder option(Class<?> type, String label, String... names) {
        return OptionSpec.builder(names).type(type).paramLabel(label);
    }

    /** An option without a value. */
    static OptionSpec.Builder flag(String... names) {
        return OptionSpec.builder(names).type(boolean.class);
    }

    /** Positional parameters of {@code type}, one or more of them. */
    static PositionalParamSpec.Builder paths(Class<?> type, String label, String description) {
        return PositionalParamSpec.builder().arity("1..*").required(true).type(List.class).auxiliaryTypes(type).paramLabel(label)
                .description(description);
    }

    /** The positional parameter at {@code index}. */
    static PositionalParamSpec.Builder parameter(String index, Class<?> type, String label, String description) {
        return PositionalParamSpec.builder().index(index).arity("1").required(true).type(type).paramLabel(label).description(description);
    }

    /** Whether {@code flag} was given. */
    static boolean given(OptionSpec flag) {
        return Boolean.TRUE.equals(flag.getValue());
    }
}
