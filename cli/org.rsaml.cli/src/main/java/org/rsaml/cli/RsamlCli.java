/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.function.Function;

import org.rsaml.diagram.DiagramFormat;
import org.rsaml.diagram.DiagramView;
import org.rsaml.generator.Target;
import org.rsaml.report.ExitCodes;
import org.rsaml.report.FindingFailOn;
import org.rsaml.report.TimingFailOn;
import org.rsaml.report.ReportFormat;
import org.rsaml.report.Text;

import picocli.CommandLine;
import picocli.CommandLine.IVersionProvider;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.ScopeType;

/**
 * {@code rsaml}: validates RsaML models headless, for terminals and CI pipelines.
 * Exit codes: 0 clean, 1 findings at or above {@code --fail-on}, 2 usage or input error.
 */
public final class RsamlCli implements Runnable {

    /** The commands, in the order help lists them, each made on demand for a tool. */
    private static final Map<String, Function<RsamlCli, RsamlCommand>> COMMANDS = new LinkedHashMap<>();

    static {
        COMMANDS.put(ValidateCommand.NAME, ValidateCommand::new);
        COMMANDS.put(GenerateCommand.NAME, GenerateCommand::new);
        COMMANDS.put(DiagramCommand.NAME, DiagramCommand::new);
        COMMANDS.put(AnalyzeCommand.NAME, AnalyzeCommand::new);
        COMMANDS.put(ConvertCommand.NAME, ConvertCommand::new);
        COMMANDS.put(LanguageServerCommand.NAME, LanguageServerCommand::new);
        COMMANDS.put(RulesCommand.NAME, RulesCommand::new);
    }

    private final OptionSpec debug = CommandSpecs.flag("--debug").scopeType(ScopeType.INHERIT)
            .description("On an unexpected failure, print the stack trace.").build();

    /** Where relative paths are resolved; the process's working directory unless embedded. */
    final Path workingDirectory;

    final CommandSpec spec;

    /** Guice's switch for the classes it generates (method interception and fast construction), read once, when it loads. */
    private static final String GUICE_CLASS_GENERATION = "guice_bytecode_gen_option";

    /**
     * picocli's switch for its built-in converters that it finds by reflection (java.sql's and java.time's types,
     * {@code Path}): regular expressions of the class names it leaves out. RsaML's options take none of those types but
     * {@code Path}, whose converter {@link #run} registers; looking them up would load the java.sql module, java.time's
     * formatters and their reflection on every run.
     */
    private static final String PICOCLI_CONVERTER_EXCLUDES = "picocli.converters.excludes";

    RsamlCli(Path workingDirectory) {
        this.workingDirectory = workingDirectory;
        spec = CommandSpecs.command("rsaml", this,
                "Checks robot software architectures written in RsaML (.rsaml files) and generates their code skeletons.");
        spec.versionProvider(new Version());
        spec.usageMessage().footer("", "Example: rsaml validate --format sarif --output junit=target/rsaml.xml models/");
        CommandSpecs.exitCodes(spec, CommandSpecs.VALIDATION_EXIT_CODES);
        spec.addOption(debug);
        CommandSpecs.standardHelpOptions(spec);
    }

    /** Whether {@code --debug} was given. */
    boolean debug() {
        return CommandSpecs.given(debug);
    }

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a command is required (validate, generate, diagram, analyze, convert, rules, help)");
    }

    public static void main(String[] args) {
        setUpProcess();
        PrintWriter out = new PrintWriter(new OutputStreamWriter(System.out, StandardCharsets.UTF_8), true);
        PrintWriter err = new PrintWriter(new OutputStreamWriter(System.err, StandardCharsets.UTF_8), true);
        int code = run(Path.of("").toAbsolutePath(), args, out, err);
        out.flush();
        err.flush();
        System.exit(code);
    }

    /**
     * Sets what a process running {@code rsaml}'s commands needs, once, before the first (the launcher's JVM, the
     * runnable jar, the language server, the resident process): Guice, which builds the text syntax's objects, does so
     * by reflection rather than by generating classes, which needs sun.misc.Unsafe and on JDK 24 and later prints
     * warnings about it that a user can do nothing about; picocli looks up none of its reflective converters. A value
     * given with -D stays.
     */
    public static void setUpProcess() {
        if (System.getProperty(GUICE_CLASS_GENERATION) == null) {
            System.setProperty(GUICE_CLASS_GENERATION, "DISABLED");
        }
        if (System.getProperty(PICOCLI_CONVERTER_EXCLUDES) == null) {
            System.setProperty(PICOCLI_CONVERTER_EXCLUDES, ".*");
        }
    }

    /** Runs {@code rsaml} in this JVM, relative paths resolved against {@code workingDirectory}. */
    public static int run(Path workingDirectory, String[] args, PrintWriter out, PrintWriter err) {
        RsamlCli cli = new RsamlCli(workingDirectory);
        CommandLine commandLine = new CommandLine(cli.spec);
        // A run of one command ("rsaml validate ...") gets that command's model alone; help, errors and the rest get
        // every one, and the help command.
        Function<RsamlCli, RsamlCommand> named = args.length > 0 ? COMMANDS.get(args[0]) : null;
        if (named != null) {
            commandLine.addSubcommand(named.apply(cli).spec);
        } else {
            COMMANDS.values().forEach(command -> commandLine.addSubcommand(command.apply(cli).spec));
            // picocli's own, read from its annotations: not on the path of a command's run.
            commandLine.addSubcommand(new CommandLine.HelpCommand());
        }
        commandLine.setOut(out);
        commandLine.setErr(err);
        commandLine.setCaseInsensitiveEnumValuesAllowed(true);
        // Every value with a name of its own is read by its type's parse, which names the value and what it can be.
        commandLine.registerConverter(ReportFormat.class, parsedBy(ReportFormat::parse));
        commandLine.registerConverter(FindingFailOn.class, parsedBy(FindingFailOn::parse));
        commandLine.registerConverter(TimingFailOn.class, parsedBy(TimingFailOn::parse));
        commandLine.registerConverter(DiagramView.class, parsedBy(DiagramView::parse));
        commandLine.registerConverter(DiagramFormat.class, parsedBy(DiagramFormat::parse));
        commandLine.registerConverter(Target.class, parsedBy(Target::parse));
        commandLine.registerConverter(Path.class, RsamlCli::path);
        commandLine.setExitCodeExceptionMapper(e -> ExitCodes.INPUT_ERROR);
        commandLine.setParameterExceptionHandler((e, arguments) -> {
            CommandLine cmd = e.getCommandLine();
            cmd.getErr().println(Text.line("rsaml: " + e.getMessage()));
            List<String> suggestions = List.of();
            if (e instanceof CommandLine.UnmatchedArgumentException unmatched && !unmatched.getUnmatched().isEmpty()
                    && !unmatched.getUnmatched().get(0).startsWith("-")) {
                suggestions = suggestions(cmd.getCommandSpec(), unmatched.getUnmatched().get(0));
            } else {
                // The first option the command does not know, also when picocli reports something else first.
                for (String argument : arguments) {
                    String option = argument.contains("=") ? argument.substring(0, argument.indexOf('=')) : argument;
                    if (option.startsWith("-") && option.length() > 1 && !option.equals("--")
                            && cmd.getCommandSpec().findOption(option) == null) {
                        suggestions = suggestions(cmd.getCommandSpec(), option);
                        break;
                    }
                }
            }
            if (!suggestions.isEmpty()) {
                cmd.getErr().println(Text.line("Did you mean " + String.join(" or ", suggestions) + "?"));
            }
            cmd.getErr().println("Try '" + cmd.getCommandSpec().qualifiedName() + " --help' for more information.");
            return ExitCodes.INPUT_ERROR;
        });
        commandLine.setExecutionExceptionHandler((e, cmd, parseResult) -> {
            if (e instanceof UserException user) {
                cmd.getErr().println(Text.line("rsaml: " + user.getMessage()));
            } else {
                cmd.getErr().println(Text.line("rsaml: internal error: " + e + (cli.debug() ? "" : " (run with --debug for details)")));
            }
            if (cli.debug()) {
                e.printStackTrace(cmd.getErr());
            }
            return ExitCodes.INPUT_ERROR;
        });
        try {
            return commandLine.execute(args);
        } catch (OutOfMemoryError e) {
            err.println("rsaml: out of memory; give the JVM more heap (RSAML_JAVA_OPTS=-Xmx4g)");
            return ExitCodes.INPUT_ERROR;
        } catch (StackOverflowError e) {
            // The commands keep a deep model to its own file; this is the last resort for whatever escapes them.
            err.println(Text.line("rsaml: internal error: the model is too deep for the stack (" + e + ", a defect in RsaML,"
                    + " please report it); a larger stack may get past it: RSAML_JAVA_OPTS=-Xss512m"));
            if (cli.debug()) {
                e.printStackTrace(err);
            }
            return ExitCodes.INPUT_ERROR;
        }
    }

    /** A converter that reads a value with {@code parse}, whose {@link IllegalArgumentException} says what is wrong. */
    private static <T> CommandLine.ITypeConverter<T> parsedBy(Function<String, T> parse) {
        return value -> {
            try {
                return parse.apply(value);
            } catch (IllegalArgumentException e) {
                throw new CommandLine.TypeConversionException(e.getMessage());
            }
        };
    }

    /** A path as picocli's built-in converter reads it ({@code Paths.get}), with its words for one that is not. */
    private static Path path(String value) {
        try {
            return Path.of(value);
        } catch (InvalidPathException e) {
            throw new CommandLine.TypeConversionException(String.format("cannot convert '%s' to %s (%s)", value, Path.class, e));
        }
    }

    /** The commands or options closest to a misspelled one ({@code valdate}, {@code --fromat}), by edit distance. */
    static List<String> suggestions(CommandSpec spec, String typed) {
        String word = typed;
        List<String> candidates = new ArrayList<>();
        if (word.startsWith("-")) {
            spec.options().stream().filter(o -> !o.hidden()).forEach(o -> candidates.addAll(List.of(o.names())));
        } else {
            candidates.addAll(spec.subcommands().keySet());
        }
        int best = Integer.MAX_VALUE;
        List<String> closest = new ArrayList<>();
        for (String candidate : candidates) {
            int d = distance(word, candidate);
            if (d < best) {
                best = d;
                closest.clear();
            }
            if (d == best) {
                closest.add(candidate);
            }
        }
        return best <= Math.max(2, word.length() / 3) ? closest : List.of();
    }

    /** Edit distance with transpositions (optimal string alignment). */
    private static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            for (int j = 0; j <= b.length(); j++) {
                if (i == 0 || j == 0) {
                    d[i][j] = i + j;
                    continue;
                }
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }

    /** With {@code --debug}: the stack trace of what made {@code file} fail. */
    void printCause(PrintWriter err, String file, Throwable cause) {
        if (debug() && cause != null) {
            err.println(Text.line(file + ": cause of the error above:"));
            cause.printStackTrace(err);
        }
    }

    /** An error the user can fix, reported as one line without a stack trace. */
    static final class UserException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        UserException(String message) {
            super(message);
        }
    }

    /** The version written into the jar at build time. */
    static final class Version implements IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] { "rsaml " + version(), "Java " + System.getProperty("java.version") };
        }
    }

    static String version() {
        Properties properties = new Properties();
        try (InputStream in = RsamlCli.class.getResourceAsStream("version.properties")) {
            if (in != null) {
                properties.load(in);
            }
        } catch (IOException e) {
            // the version is informative only
        }
        return properties.getProperty("version", "unknown");
    }
}
