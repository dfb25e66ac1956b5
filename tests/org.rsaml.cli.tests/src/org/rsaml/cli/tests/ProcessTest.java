/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.FileTime;
import java.util.List;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.rsaml.tests.support.ExpectedFinding;
import org.junit.jupiter.api.io.TempDir;

/** The runnable jar and the ./rsaml launcher, as separate processes, the way CI and people call them. */
class ProcessTest {

    @Test
    void runnableJarValidatesTheExamples() throws Exception {
        Cli.Result r = Cli.process(Cli.ROOT, Cli.java(List.of(), "validate", "examples/"));
        assertEquals(1, r.code(), r::toString);
        List<String> lines = r.outLines();
        assertEquals(ValidateCommandTest.EXAMPLES_FINDINGS, ValidateCommandTest.findingLines(lines), r::toString);
        assertEquals(ValidateCommandTest.EXAMPLES_CLEAN, ValidateCommandTest.cleanLines(lines), r::toString);
        assertEquals("", r.err(), "a clean run writes nothing to standard error");
    }

    @Test
    void runnableJarExitCodes() throws Exception {
        assertEquals(0, Cli.process(Cli.ROOT, Cli.java(List.of(), "validate", "examples/exp3-task-interpreter.rsaml")).code(), "the runnable jar exits 0 on a clean model");
        Cli.Result usage = Cli.process(Cli.ROOT, Cli.java(List.of(), "validate", "--format"));
        assertEquals(2, usage.code(), usage::toString);
        Cli.Result missing = Cli.process(Cli.ROOT, Cli.java(List.of(), "validate", "nowhere.rsaml"));
        assertEquals(2, missing.code(), missing::toString);
        assertEquals("nowhere.rsaml: error: no such file or directory", missing.outLines().get(0), "the jar's error names the missing file");
        BadInputTest.assertNoStackTrace(missing);
    }

    @Test
    void emfMessagesSurviveInTheRunnableJar() throws Exception {
        // EMF reads its messages from plugin.properties at the jar's root; the runnable jar merges them.
        Cli.Result r = Cli.process(Cli.ROOT, Cli.java(List.of(), "validate",
                "tests/org.rsaml.validation.tests/resources/rules/rule-RSA-00-violated.rsaml"));
        assertEquals(1, r.code(), r::toString);
        assertTrue(r.out().contains("error RSA-00: The required feature 'target' of 'Connection 'robot/s0 -> <none>'' must be set"), r::toString);
    }

    @Test
    void launcherAtTheRepositoryRoot() throws Exception {
        assertTrue(Files.isExecutable(Cli.ROOT.resolve("rsaml")), "./rsaml is executable");
        Cli.Result r = Cli.process(Cli.ROOT, List.of("./rsaml", "validate", "examples/"));
        assertEquals(1, r.code(), r::toString);
        for (String finding : ValidateCommandTest.EXAMPLES_FINDINGS) {
            assertTrue(r.out().contains(finding + "\n"), () -> "the launcher prints " + finding + "\n" + r);
        }
        assertTrue(r.out().endsWith(ValidateCommandTest.examplesSummary() + "\n"), r::toString);
        // A second run uses the class-data archive the first one left; the result is the same.
        Cli.Result again = Cli.process(Cli.ROOT, List.of("./rsaml", "validate", "--format", "json", "examples/exp2-defects.rsaml"));
        assertEquals(1, again.code(), again::toString);
        assertEquals("", again.err(), "nothing but the report, no JVM warnings");
        for (ExpectedFinding e : ValidateCommandTest.exp2()) {
            assertTrue(again.out().contains("\"ruleId\": \"" + e.ruleId() + "\""), () -> "the JSON report has " + e.what() + "\n" + again);
        }
    }

    @Test
    void launcherReadsAndWritesTextModelsWithNothingOnStandardError(@TempDir Path dir) throws Exception {
        // The text syntax goes through Xtext and its injector (Guice), which on JDK 24 and later would warn about
        // sun.misc.Unsafe on every run; the JDK the tests run on is the one the launcher is given (CI: 25).
        Path text = dir.resolve("exp2-defects.rsa");
        Cli.Result convert = Cli.process(Cli.ROOT, List.of("./rsaml", "convert", "examples/exp2-defects.rsaml", text.toString()));
        assertEquals(0, convert.code(), convert::toString);
        assertEquals("", convert.err(), "converting to text writes nothing to standard error");
        Cli.Result validate = Cli.process(Cli.ROOT, List.of("./rsaml", "validate", text.toString()));
        assertEquals(1, validate.code(), validate::toString);
        assertTrue(validate.out().endsWith(ValidateCommandTest.exp2Summary() + "\n"), () -> "the text model has exp2's findings: " + validate);
        assertEquals("", validate.err(), "validating a text model writes nothing to standard error");
    }

    @Test
    void launcherInACopiedTreeMakesItsClassDataAgainUsesItAndShowsARefusal(@TempDir Path dir) throws Exception {
        // As a tree copied, moved or restored from a CI cache with its files' times kept: the jar, the launcher and
        // the class data made for the repository's own path, now somewhere else.
        Path tree = copyTree(dir.resolve("tree"));
        Path target = tree.resolve("cli/org.rsaml.cli/target");
        Path log = dir.resolve("classes-loaded.log");
        List<String> validate = List.of("env", "RSAML_JAVA_OPTS=-Xlog:class+load=info:file=" + log, "./rsaml", "validate",
                "examples/exp2-defects.rsaml");

        Cli.Result r = Cli.process(tree, validate);
        assertEquals(1, r.code(), r::toString);
        assertTrue(r.out().endsWith(ValidateCommandTest.exp2Summary() + "\n"), r::toString);
        assertEquals("", r.err(), "no JVM warning: the class data was made again for this tree and accepted");
        String loaded = Files.readString(log);
        assertTrue(loaded.contains("org.rsaml.cli.ValidateCommand source: shared objects file"),
                () -> "RsaML's classes come from the class data made for this tree (AOT cache or CDS archive):\n"
                        + loaded.lines().filter(l -> l.contains("org.rsaml.cli.")).toList());
        // picocli's published jar is Java 5 bytecode, which no class data takes; the jar carries it built for Java 17.
        assertTrue(loaded.contains("picocli.CommandLine$Model$CommandSpec source: shared objects file"),
                () -> "picocli's classes come from the class data too, not from the jar:\n"
                        + loaded.lines().filter(l -> l.contains(" picocli.") && !l.contains("shared objects file")).limit(5).toList());
        // A command's model is built by code: reading picocli's annotations would make the JVM generate proxy classes.
        assertFalse(loaded.contains(" picocli.CommandLine$Option "),
                () -> "no picocli annotation is read when a command runs:\n"
                        + loaded.lines().filter(l -> l.contains("picocli.CommandLine$Option") || l.contains("$Proxy")).toList());
        // Nor are picocli's converters that it finds by reflection (java.sql's and java.time's types): none of RsaML's
        // options has such a type, and the look-up would load the java.sql module and java.time's formatters.
        assertFalse(loaded.contains(" java.sql.") || loaded.contains(" java.time.format."),
                () -> "no java.sql or java.time.format class is loaded when a command runs:\n"
                        + loaded.lines().filter(l -> l.contains(" java.sql.") || l.contains(" java.time.format.")).limit(5).toList());
        // Nor is EMF's validator for Ecore's own data types, whose set-up builds the XML Schema types' regular
        // expressions: RsaML's attributes of those types are checked without it (RsamlModelValidator).
        assertFalse(loaded.contains(" org.eclipse.emf.ecore.util.EcoreValidator "),
                () -> "EMF's validator for Ecore is not set up when a command runs:\n"
                        + loaded.lines().filter(l -> l.contains(" org.eclipse.emf.ecore.xml.type.")).limit(5).toList());

        // The jar is replaced where it was, its old modification time put back (a copy that keeps times, a restored
        // cache): its status-change time differs, so the stamp no longer fits and the class data is made again.
        Path jar = target.resolve("rsaml.jar");
        // The class data of the JDK the launcher runs is the one whose stamp names this tree's jar (the AOT cache on
        // JDK 25 or later, else the CDS archive; the other, if any, was copied with the tree).
        Path aotStamp = target.resolve("rsaml.aot.stamp");
        String jarPath = " " + jar.toRealPath() + " ";
        boolean aot = Files.exists(aotStamp) && Files.readString(aotStamp).contains(jarPath);
        Path data = target.resolve(aot ? "rsaml.aot" : "rsaml.jsa");
        assertTrue(Files.readString(target.resolve(data.getFileName() + ".stamp")).contains(jarPath),
                () -> "the launcher made class data for this tree: " + data);
        FileTime jarTime = Files.getLastModifiedTime(jar);
        FileTime made = Files.getLastModifiedTime(data);
        Files.copy(jar, dir.resolve("rsaml.jar"), StandardCopyOption.COPY_ATTRIBUTES);
        Thread.sleep(1100);
        Files.copy(dir.resolve("rsaml.jar"), jar, StandardCopyOption.REPLACE_EXISTING);
        Files.setLastModifiedTime(jar, jarTime);
        Cli.Result replaced = Cli.process(tree, validate);
        assertEquals(r.out(), replaced.out(), "the same report after the jar was replaced");
        assertEquals("", replaced.err(), "no JVM warning: the class data was made again for the replaced jar and accepted");
        FileTime remade = Files.getLastModifiedTime(data);
        assertTrue(remade.compareTo(made) > 0,
                () -> "the class data " + data.getFileName() + " was made again for the replaced jar (made " + made + ", now "
                        + remade + ")");
        String reloaded = Files.readString(log);
        assertTrue(reloaded.contains("org.rsaml.cli.ValidateCommand source: shared objects file"),
                () -> "RsaML's classes come from the class data made again:\n"
                        + reloaded.lines().filter(l -> l.contains("org.rsaml.cli.")).toList());

        // The jar changes under class data whose stamp still claims to fit it (as if the stamp were written for the new
        // jar). A CDS archive (JDK 17 to 24) is then refused by the JVM itself, which says so on standard error; the
        // run itself is unchanged. An AOT cache (JDK 25 or later) is checked by the stamp alone (the JVM does not
        // compare the jar when the cache holds all the classes a run loads from it): it is refused, and says so, when
        // the run's options no longer fit it (compressed object pointers off, as -Xmx above 32 GB does).
        long changed = Files.getLastModifiedTime(jar).toMillis() / 1000 + 3600;
        Files.setLastModifiedTime(jar, FileTime.fromMillis(changed * 1000));
        long statusChanged = ((FileTime) Files.getAttribute(jar, "unix:ctime")).toMillis() / 1000;
        Path stamp = target.resolve(data.getFileName() + ".stamp");
        // The stamp starts with the jar's size, modification and status-change times in seconds (stat -c '%s %Y %Z').
        String[] fields = Files.readString(stamp).split(" ", 4);
        Files.writeString(stamp, fields[0] + " " + changed + " " + statusChanged + " " + fields[3]);
        List<String> refusedRun = aot
                ? List.of("env", "RSAML_JAVA_OPTS=-XX:-UseCompressedOops", "./rsaml", "validate", "examples/exp2-defects.rsaml")
                : validate;
        Cli.Result refused = Cli.process(tree, refusedRun);
        assertEquals(1, refused.code(), refused::toString);
        assertEquals(r.out(), refused.out(), "the same report without the class data");
        assertTrue(refused.err().contains("archive") || refused.err().contains("AOT cache"),
                () -> "the JVM's refusal of the class data is shown, not hidden:\n" + refused);
    }

    /** The launcher, the jar with its class data, the resident process's client and one example, copied to {@code tree} with their files' times. */
    static Path copyTree(Path tree) throws Exception {
        Path target = Files.createDirectories(tree.resolve("cli/org.rsaml.cli/target"));
        Files.createDirectories(tree.resolve("examples"));
        Files.copy(Cli.ROOT.resolve("rsaml"), tree.resolve("rsaml"), StandardCopyOption.COPY_ATTRIBUTES);
        Files.copy(Cli.ROOT.resolve("examples/exp2-defects.rsaml"), tree.resolve("examples/exp2-defects.rsaml"));
        Path built = Cli.ROOT.resolve("cli/org.rsaml.cli/target");
        for (String name : List.of("rsaml.jar", "rsaml.jsa", "rsaml.jsa.stamp", "rsaml.aot", "rsaml.aot.stamp",
                "rsaml-client.jar")) {
            if (Files.exists(built.resolve(name))) {
                Files.copy(built.resolve(name), target.resolve(name), StandardCopyOption.COPY_ATTRIBUTES);
            }
        }
        return tree;
    }

    @Test
    void launcherInAReadOnlyTreeKeepsItsClassDataInTheUsersCache(@TempDir Path dir) throws Exception {
        // A tree whose class data was made where it was written, then used read-only at another path (an installed
        // or mounted tree): the class data beside the jar does not fit and that folder cannot be written.
        Path tree = copyTree(dir.resolve("tree"));
        Path ro = Files.createDirectories(dir.resolve("ro"));
        Path cache = dir.resolve("cache");
        Path log = dir.resolve("classes-loaded.log");
        List<String> validate = List.of("./rsaml", "validate", "examples/exp2-defects.rsaml");
        Cli.Result normal = Cli.process(tree, validate);
        assertEquals(1, normal.code(), normal::toString);
        assertTrue(normal.out().endsWith(ValidateCommandTest.exp2Summary() + "\n"), normal::toString);

        // The tree is made read-only where this user can, checked by the run itself before the launcher starts (a
        // 'touch' beside the jar must fail): as root (CI, containers), for whom file permissions do not stop writes, by a
        // read-only bind mount in a mount namespace of the run's own, or else by taking away root's power to override
        // file permissions (setpriv) in a tree made read-only; as another user, by making the tree read-only.
        ReadOnly readOnlyTree = ReadOnly.make(dir, tree, ro);
        if (readOnlyTree.prefix() == null) {
            // Neither works here (root without the privileges to mount or to drop its own): reported as skipped, with
            // why, since the rest of this test needs a tree that cannot be written. CI has them; it must not get here.
            Assumptions.abort("not checked here: the launcher in a read-only tree (class data in the user's cache,"
                    + " or none, said in one line), since no tree can be made read-only for this user: " + readOnlyTree.why());
        }
        String script = "cd \"$2\" && if touch cli/org.rsaml.cli/target/probe 2>/dev/null; then echo 'the tree is writable' >&2; exit 99; fi"
                + " && exec env XDG_CACHE_HOME=\"$3\" RSAML_JAVA_OPTS=-Xlog:class+load=info:file=\"$4\" ./rsaml validate examples/exp2-defects.rsaml";
        List<String> readOnly = readOnlyTree.command(script, cache.toString(), log.toString());
        try {
            Cli.Result first = Cli.process(dir, readOnly);
            assertEquals(normal.code(), first.code(), first::toString);
            assertEquals(normal.out(), first.out(), "the same report as in a writable tree");
            assertEquals("", first.err(), "no error and no JVM warning: the class data was made in the user's cache");
            List<Path> kept;
            try (var folders = Files.list(cache.resolve("rsaml"))) {
                kept = folders.toList();
            }
            assertEquals(1, kept.size(), () -> "one folder of class data for this jar: " + kept);
            assertEquals("rwx------", java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(kept.get(0))),
                    "the user's class data is the user's alone");
            Path data;
            try (var files = Files.list(kept.get(0))) {
                data = files.filter(f -> f.toString().endsWith(".jsa") || f.toString().endsWith(".aot")).findFirst().orElseThrow();
            }
            String loaded = Files.readString(log);
            assertTrue(loaded.contains("org.rsaml.cli.ValidateCommand source: shared objects file"),
                    () -> "RsaML's classes come from the class data in the user's cache");
            Object made = Files.readAttributes(data, java.nio.file.attribute.BasicFileAttributes.class).fileKey();
            FileTime madeAt = Files.getLastModifiedTime(data);

            Cli.Result second = Cli.process(dir, readOnly);
            assertEquals(normal.code(), second.code(), second::toString);
            assertEquals(normal.out(), second.out(), "the same report again");
            assertEquals("", second.err(), second::toString);
            assertEquals(made, Files.readAttributes(data, java.nio.file.attribute.BasicFileAttributes.class).fileKey(),
                    "no training on every run: the second run used the class data the first one made");
            assertEquals(madeAt, Files.getLastModifiedTime(data), "the class data was not made again");

            // Nowhere to keep class data (the cache is inside the read-only tree): the run goes on without it, and says why.
            List<String> nowhere = new java.util.ArrayList<>(readOnly);
            nowhere.set(nowhere.size() - 2, ro.resolve("examples/cache").toString());
            Cli.Result without = Cli.process(dir, nowhere);
            assertEquals(normal.code(), without.code(), without::toString);
            assertEquals(normal.out(), without.out(), "the same report without class data");
            assertTrue(without.err().startsWith("rsaml: starting without class data: neither ")
                    && without.err().lines().count() == 1, () -> "one line on standard error says why:\n" + without);
        } finally {
            readOnlyTree.undo();
        }
    }

    /**
     * A way to run a command in a tree that cannot be written: {@code prefix} before {@code sh -c}, {@code mount} the
     * shell commands that make the tree's read-only view first; {@code chmod} when the tree's files were made read-only
     * (and must be made writable again); {@code prefix} {@code null} when no way works for this user, {@code why} says why.
     */
    private record ReadOnly(List<String> prefix, String mount, boolean chmod, Path tree, Path ro, String why) {

        static final String MOUNT = "mount --bind \"$1\" \"$2\" && mount -o remount,bind,ro \"$2\" && ";

        /** The first way that makes {@code tree} a read-only tree at {@code ro} here, proven by a probe run. */
        static ReadOnly make(Path dir, Path tree, Path ro) throws Exception {
            boolean root = "0".equals(Cli.process(dir, List.of("id", "-u")).out().strip());
            List<String> failures = new java.util.ArrayList<>();
            if (root) {
                ReadOnly mounted = new ReadOnly(List.of("unshare", "-m"), MOUNT, false, tree, ro, null);
                if (mounted.probe(dir, failures)) {
                    return mounted;
                }
                if (mayMount()) {
                    // CI's case: the privilege is there, so a failing mount is a failure, not a missing privilege.
                    throw new AssertionError("root with CAP_SYS_ADMIN could not bind-mount the tree read-only: " + failures);
                }
            }
            Files.delete(ro);
            Files.move(tree, ro);
            assertEquals(0, Cli.process(dir, List.of("chmod", "-R", "a-w", ro.toString())).code(), "the moved tree is made read-only");
            ReadOnly chmod = new ReadOnly(root ? List.of("setpriv", "--inh-caps=-dac_override,-dac_read_search",
                    "--bounding-set=-dac_override,-dac_read_search") : List.of(), "", true, tree, ro, null);
            if (chmod.probe(dir, failures)) {
                return chmod;
            }
            chmod.undo();
            return new ReadOnly(null, "", false, tree, ro, String.join("; ", failures));
        }

        /** Whether this process may mount (CAP_SYS_ADMIN among its effective capabilities). */
        private static boolean mayMount() throws Exception {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("CapEff:")) {
                    return (Long.parseUnsignedLong(line.substring(7).strip(), 16) & (1L << 21)) != 0;
                }
            }
            return false;
        }

        /** Whether a run this way finds the tree unwritable; what went wrong otherwise is added to {@code failures}. */
        private boolean probe(Path dir, List<String> failures) throws Exception {
            Cli.Result r = Cli.process(dir, command("cd \"$2\" && if touch cli/org.rsaml.cli/target/probe 2>/dev/null;"
                    + " then echo 'the tree is still writable' >&2; exit 99; fi", "", ""));
            if (r.code() != 0) {
                failures.add(String.join(" ", prefix.isEmpty() ? List.of("chmod -R a-w") : prefix) + ": "
                        + r.err().strip().lines().findFirst().orElse("exit code " + r.code()));
            }
            return r.code() == 0;
        }

        /** {@code script} run this way, with the tree, its read-only place, the cache and the log as $1 to $4. */
        List<String> command(String script, String cache, String log) {
            List<String> command = new java.util.ArrayList<>(prefix);
            command.addAll(List.of("sh", "-c", mount + script, "sh", tree.toString(), ro.toString(), cache, log));
            return command;
        }

        void undo() throws Exception {
            if (chmod) {
                Cli.process(ro.getParent(), List.of("chmod", "-R", "u+w", ro.toString()));
            }
        }
    }

    @Test
    void launcherSymlinkedOntoThePathRunsFromAnotherDirectory(@TempDir Path dir) throws Exception {
        // As after 'ln -s ~/rsaml/rsaml ~/bin/rsaml': a link to a link, called from elsewhere.
        Path bin = Files.createDirectories(dir.resolve("bin"));
        Path tools = Files.createDirectories(dir.resolve("tools"));
        Files.createSymbolicLink(tools.resolve("rsaml"), Cli.ROOT.resolve("rsaml"));
        Files.createSymbolicLink(bin.resolve("rsaml"), Path.of("../tools/rsaml"));
        Path work = Files.createDirectories(dir.resolve("work"));
        Files.copy(Cli.ROOT.resolve("examples/exp2-defects.rsaml"), work.resolve("model.rsaml"));

        // As after 'ln -s ../tools/rsaml r2' in the model's folder, then 'bash r2 ...': a relative link named without a slash.
        Files.createSymbolicLink(work.resolve("r2"), Path.of("../tools/rsaml"));

        Cli.Result r = Cli.process(work, List.of(bin.resolve("rsaml").toString(), "validate", "model.rsaml"));
        Cli.Result here = Cli.process(work, List.of("bash", "r2", "validate", "model.rsaml"));
        // The link out of the temporary folder goes now, so JUnit need not warn about it.
        Files.delete(tools.resolve("rsaml"));
        for (Cli.Result run : List.of(r, here)) {
            assertEquals(1, run.code(), () -> "exp2's findings give exit code 1: " + run);
            assertTrue(run.out().startsWith("model.rsaml:"), () -> "the report names the model as given: " + run);
            assertTrue(run.out().endsWith(ValidateCommandTest.exp2Summary() + "\n"), () -> "the report ends with exp2's summary: " + run);
            assertEquals("", run.err(), "no first-use build and no error: the launcher found its jar through the links");
        }
    }
}
