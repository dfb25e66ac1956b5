/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.jar.Manifest;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * README's repository structure and docs/architecture.md stay true: every module folder is listed,
 * every bundle is described, and the dependencies the page states are the ones the manifests and
 * poms declare.
 */
class RepositoryDocsTest {

    private static final Path ROOT = Cli.ROOT;
    private static final Pattern RSAML_ID = Pattern.compile("org\\.rsaml\\.[a-z.]*[a-z]");

    @Test
    void theReadmeStructureListsEveryModuleFolder() throws Exception {
        String readme = Files.readString(ROOT.resolve("README.md"));
        int start = readme.indexOf("## Repository structure");
        assertTrue(start >= 0, "README has a repository-structure section");
        int open = readme.indexOf("```", start);
        String block = readme.substring(open + 3, readme.indexOf("```", open + 3));
        List<String> missing = new ArrayList<>();
        for (String parent : List.of("bundles", "cli", "tests", "features", "releng", "maven")) {
            assertTrue(block.contains("\n" + parent + "/"), () -> "README structure names " + parent + "/");
            for (Path dir : folders(ROOT.resolve(parent))) {
                if (!Pattern.compile("\\n {2}" + Pattern.quote(dir.getFileName().toString()) + "/").matcher(block).find()) {
                    missing.add(parent + "/" + dir.getFileName());
                }
            }
        }
        assertEquals(List.of(), missing, "folders missing from README's repository structure");
    }

    /**
     * Every entry at the top of the repository (files and folders; what .gitignore leaves out apart) is named at the
     * start of a line of the structure, alone or in a list ({@code LICENSE, NOTICE}, {@code .ci/run}), and every entry
     * named there exists.
     */
    @Test
    void theReadmeStructureNamesEveryTopLevelEntry() throws Exception {
        String readme = Files.readString(ROOT.resolve("README.md"));
        int open = readme.indexOf("```", readme.indexOf("## Repository structure"));
        String block = readme.substring(open + 3, readme.indexOf("```", open + 3));
        Set<String> named = new TreeSet<>();
        List<String> absent = new ArrayList<>();
        for (String line : block.split("\n")) {
            if (!line.isBlank() && !line.startsWith(" ")) {
                for (String entry : line.split(" {2,}")[0].split(",")) {
                    named.add(entry.strip().split("/")[0]);
                    if (!Files.exists(ROOT.resolve(entry.strip()))) {
                        absent.add(entry.strip());
                    }
                }
            }
        }
        assertEquals(List.of(), absent, "entries README's repository structure names at the top that the repository does not have");
        Set<String> ignored = new TreeSet<>(Set.of(".git"));
        for (String pattern : Files.readAllLines(ROOT.resolve(".gitignore"))) {
            String name = pattern.strip().replaceAll("^/|/$", "");
            if (!name.isEmpty() && !name.contains("/") && !name.contains("*")) {
                ignored.add(name);
            }
        }
        List<String> unnamed = new ArrayList<>();
        try (Stream<Path> entries = Files.list(ROOT)) {
            entries.map(e -> e.getFileName().toString()).filter(n -> !ignored.contains(n) && !named.contains(n)).sorted().forEach(unnamed::add);
        }
        assertEquals(List.of(), unnamed, "top-level entries README's repository structure does not name (it names " + named + ")");
    }

    /** One test bundle per production bundle ({@code bundles/x} is tested by {@code tests/x.tests}), as STYLE.md asks. */
    @Test
    void everyBundleHasItsTestBundle() throws Exception {
        List<String> untested = new ArrayList<>();
        for (Path dir : folders(ROOT.resolve("bundles"))) {
            if (!Files.isRegularFile(ROOT.resolve("tests").resolve(dir.getFileName() + ".tests").resolve("pom.xml"))) {
                untested.add(dir.getFileName().toString());
            }
        }
        assertEquals(List.of(), untested, "bundles without a test bundle tests/<bundle>.tests");
    }

    /** The other way round: every folder the structure names below a top-level folder is there. */
    @Test
    void theReadmeStructureNamesOnlyFoldersThatExist() throws Exception {
        String readme = Files.readString(ROOT.resolve("README.md"));
        int open = readme.indexOf("```", readme.indexOf("## Repository structure"));
        String block = readme.substring(open + 3, readme.indexOf("```", open + 3));
        Pattern top = Pattern.compile("^([A-Za-z0-9._-]+)/\\s*$");
        Pattern child = Pattern.compile("^ {2}([A-Za-z0-9._-]+)/\\s");
        String parent = null;
        List<String> absent = new ArrayList<>();
        for (String line : block.split("\n")) {
            Matcher t = top.matcher(line);
            Matcher c = child.matcher(line);
            if (t.find()) {
                parent = t.group(1);
            } else if (!line.startsWith(" ")) {
                parent = null;
            } else if (parent != null && c.find() && !Files.isDirectory(ROOT.resolve(parent).resolve(c.group(1)))) {
                absent.add(parent + "/" + c.group(1));
            }
        }
        assertEquals(List.of(), absent, "folders README's repository structure names but the repository does not have");
    }

    /**
     * {@code bundles/} holds OSGi bundles only (a manifest each); a plain Maven artifact such as the
     * command-line jar lives apart, as EMF, Xtext and ELK keep theirs.
     */
    @Test
    void bundlesHoldsOnlyBundles() throws Exception {
        List<String> plain = new ArrayList<>();
        for (Path dir : folders(ROOT.resolve("bundles"))) {
            if (!Files.exists(dir.resolve("META-INF/MANIFEST.MF"))) {
                plain.add("bundles/" + dir.getFileName());
            }
        }
        assertEquals(List.of(), plain, "folders under bundles/ without META-INF/MANIFEST.MF (not OSGi bundles)");
    }

    /** The module paths README's commands and the ./rsaml launcher build ({@code -pl a,b}) are modules of the build. */
    @Test
    void theCommandsBuildModulesThatExist() throws Exception {
        Pattern pl = Pattern.compile("-pl '?([A-Za-z0-9._/,-]+)");
        List<String> absent = new ArrayList<>();
        for (String file : List.of("README.md", "rsaml")) {
            Matcher m = pl.matcher(Files.readString(ROOT.resolve(file)));
            while (m.find()) {
                for (String module : m.group(1).split(",")) {
                    if (module.contains("/") && !Files.exists(ROOT.resolve(module).resolve("pom.xml"))) {
                        absent.add(file + ": -pl " + module);
                    }
                }
            }
        }
        assertEquals(List.of(), absent, "modules named by README's and the launcher's build commands that have no pom.xml");
    }

    @Test
    void theArchitecturePageDescribesEveryBundle() throws Exception {
        String page = Files.readString(ROOT.resolve("docs/architecture.md"));
        List<String> missing = new ArrayList<>();
        for (Path dir : Stream.concat(folders(ROOT.resolve("bundles")).stream(), folders(ROOT.resolve("cli")).stream()).toList()) {
            if (!page.contains("| `" + dir.getFileName() + "`")) {
                missing.add(dir.getFileName().toString());
            }
        }
        assertEquals(List.of(), missing, "bundles without a row in docs/architecture.md");
    }

    /**
     * The classes a bundle's row names are RsaML's: {@code support.RsamlTimes} is in that bundle's package
     * {@code ...support}, {@code ModelBatch} is a source file of some RsaML module (another framework's class is
     * named as its, "EMF's stock {@code Diagnostician}", and not checked).
     */
    @Test
    void theArchitecturePageNamesClassesThatExist() throws Exception {
        String page = Files.readString(ROOT.resolve("docs/architecture.md"));
        List<Path> sources = new ArrayList<>();
        for (String top : List.of("bundles", "cli", "maven")) {
            try (Stream<Path> files = Files.walk(ROOT.resolve(top))) {
                files.filter(f -> f.toString().endsWith(".java") || f.toString().endsWith(".xtend"))
                        .filter(f -> !f.toString().contains("/target/") && !f.toString().contains("/src/it/")).forEach(sources::add);
            }
        }
        Pattern named = Pattern.compile("('s (?:stock )?)?`((?:[a-z][a-z0-9]*\\.)*)([A-Z][A-Za-z0-9]*)(?:\\.[A-Z][A-Za-z0-9]*)?`");
        Matcher row = Pattern.compile("(?m)^\\| `([a-z][a-z.\\-]*)`[^|]*\\|(.*)$").matcher(page);
        List<String> absent = new ArrayList<>();
        int checked = 0;
        while (row.find()) {
            String module = row.group(1);
            Path dir = Stream.of("bundles", "cli", "maven").map(top -> ROOT.resolve(top).resolve(module)).filter(Files::isDirectory)
                    .findFirst().orElseThrow(() -> new AssertionError("docs/architecture.md has a row for " + module + ", which is no module"));
            Matcher m = named.matcher(row.group(2));
            while (m.find()) {
                if (m.group(1) != null) {
                    continue;
                }
                String qualifier = m.group(2).isEmpty() ? null : "/" + m.group(2).replace('.', '/');
                String type = m.group(3);
                boolean found = sources.stream().anyMatch(f -> {
                    String name = f.getFileName().toString();
                    boolean isType = name.equals(type + ".java") || name.equals(type + ".xtend");
                    return isType && (qualifier == null || f.startsWith(dir) && f.getParent().toString().replace('\\', '/').endsWith(
                            qualifier.substring(0, qualifier.length() - 1)));
                });
                checked++;
                if (!found) {
                    absent.add(module + ": " + m.group(2) + type);
                }
            }
        }
        assertTrue(checked > 0, "the page's bundle table names classes");
        assertEquals(List.of(), absent, "classes docs/architecture.md names that are not in the module (or package) it says");
    }

    @Test
    void theStatedDependenciesAreTheDeclaredOnes() throws Exception {
        TreeMap<String, Set<String>> stated = statedDependencies();
        TreeMap<String, Set<String>> declared = new TreeMap<>();
        for (Path dir : folders(ROOT.resolve("bundles"))) {
            String name = dir.getFileName().toString();
            Path manifest = dir.resolve("META-INF/MANIFEST.MF");
            if (Files.exists(manifest)) {
                try (InputStream in = Files.newInputStream(manifest)) {
                    declared.put(name, rsamlIds(new Manifest(in).getMainAttributes().getValue("Require-Bundle")));
                }
            } else {
                declared.put(name, pomDependencies(dir.resolve("pom.xml")));
            }
        }
        for (Path dir : folders(ROOT.resolve("cli"))) {
            declared.put(dir.getFileName().toString(), pomDependencies(dir.resolve("pom.xml")));
        }
        declared.put("rsaml-maven-plugin", pomDependencies(ROOT.resolve("maven/rsaml-maven-plugin/pom.xml")));
        assertEquals(declared, stated, "docs/architecture.md's dependency list against the manifests and poms");
    }

    /**
     * A bundle requires another RsaML bundle only when it uses it: some source, plugin.xml or OSGi
     * component of it names a class of a package the other exports. An unused requirement is a false
     * line on the page above and a dependency every user installs for nothing.
     */
    @Test
    void everyRequiredBundleIsUsed() throws Exception {
        // Used without naming a class: Sirius draws labels and icons through the item providers EMF.Edit registers.
        Set<String> byRegistration = Set.of("org.rsaml.design requires org.rsaml.model.edit");
        List<String> unused = new ArrayList<>();
        for (Path dir : folders(ROOT.resolve("bundles"))) {
            Path manifest = dir.resolve("META-INF/MANIFEST.MF");
            if (!Files.exists(manifest)) {
                continue;
            }
            String text = sources(dir);
            for (String required : rsamlIds(attribute(manifest, "Require-Bundle"))) {
                Path other = ROOT.resolve("bundles").resolve(required).resolve("META-INF/MANIFEST.MF");
                if (!Files.exists(other)) {
                    continue;
                }
                boolean used = false;
                for (String clause : attribute(other, "Export-Package").split(",(?=[^\"]*(\"[^\"]*\"[^\"]*)*$)")) {
                    String pkg = clause.split(";", 2)[0].strip();
                    used |= Pattern.compile("\\b" + Pattern.quote(pkg) + "\\.[A-Z]").matcher(text).find();
                }
                if (!used && !byRegistration.contains(dir.getFileName() + " requires " + required)) {
                    unused.add(dir.getFileName() + " requires " + required);
                }
            }
        }
        assertEquals(List.of(), unused, "requirements of which no class is used");
    }

    private static String attribute(Path manifest, String name) throws Exception {
        try (InputStream in = Files.newInputStream(manifest)) {
            String value = new Manifest(in).getMainAttributes().getValue(name);
            return value == null ? "" : value;
        }
    }

    /** The hand-written and generated sources, templates, plugin.xml and OSGi components of a bundle, as one text. */
    private static String sources(Path bundle) throws Exception {
        StringBuilder text = new StringBuilder();
        try (Stream<Path> files = Files.walk(bundle)) {
            for (Path f : files.filter(Files::isRegularFile).filter(f -> !bundle.relativize(f).startsWith("target")).toList()) {
                String name = f.getFileName().toString();
                if (name.endsWith(".java") || name.endsWith(".xtend") || name.equals("plugin.xml")
                        || f.getParent().getFileName().toString().equals("OSGI-INF")) {
                    text.append(Files.readString(f)).append('\n');
                }
            }
        }
        return text.toString();
    }

    /** The page's "bundle → requirements" lines; "a, b → x" states the same requirements for both. */
    private static TreeMap<String, Set<String>> statedDependencies() throws Exception {
        String page = Files.readString(ROOT.resolve("docs/architecture.md"));
        int section = page.indexOf("## Direction of dependencies");
        int open = page.indexOf("```", section);
        String block = page.substring(open + 3, page.indexOf("```", open + 3));
        TreeMap<String, Set<String>> stated = new TreeMap<>();
        for (String line : block.strip().split("\n")) {
            String[] sides = line.split("→", 2);
            Set<String> requires = new TreeSet<>();
            if (sides.length == 2) {
                for (String r : sides[1].replaceAll("\\(.*\\)", "").split(",")) {
                    requires.add("org.rsaml." + r.strip());
                }
            }
            for (String b : sides[0].split(",")) {
                String id = b.strip();
                stated.put(id.equals("plugin") ? "rsaml-maven-plugin" : id, requires);
            }
        }
        return stated;
    }

    private static Set<String> pomDependencies(Path pom) throws Exception {
        String text = Files.readString(pom);
        String deps = text.substring(text.indexOf("<dependencies>"), text.indexOf("</dependencies>"));
        Set<String> ids = new TreeSet<>();
        // what the module's code uses: its tests' dependencies (the test support) are not the module's
        Matcher dependency = Pattern.compile("<dependency>.*?</dependency>", Pattern.DOTALL).matcher(deps);
        while (dependency.find()) {
            Matcher m = Pattern.compile("<artifactId>(org\\.rsaml\\.[a-z.]*[a-z])</artifactId>").matcher(dependency.group());
            if (m.find() && !dependency.group().contains("<scope>test</scope>")) {
                ids.add(m.group(1));
            }
        }
        return ids;
    }

    private static Set<String> rsamlIds(String requireBundle) {
        Set<String> ids = new TreeSet<>();
        if (requireBundle != null) {
            for (String clause : requireBundle.split(",(?=[^\"]*(\"[^\"]*\"[^\"]*)*$)")) {
                String id = clause.split(";", 2)[0].strip();
                if (RSAML_ID.matcher(id).matches()) {
                    ids.add(id);
                }
            }
        }
        return ids;
    }

    private static List<Path> folders(Path parent) throws Exception {
        try (Stream<Path> s = Files.list(parent)) {
            return s.filter(Files::isDirectory)
                    .filter(d -> !d.getFileName().toString().startsWith(".") && !d.getFileName().toString().equals("target"))
                    .sorted().toList();
        }
    }

    /**
     * The update site lists the third-party bundles it carries twice, for Java 17 (category.xml) and for the build with
     * the editors (ide/category.xml): the second carries everything the first does, or the runtime feature cannot be
     * installed from the full site.
     */
    @Test
    void theFullUpdateSiteCarriesEveryBundleOfTheRuntimeSite() throws Exception {
        Pattern bundle = Pattern.compile("<bundle id=\"([^\"]+)\"");
        Path site = Cli.ROOT.resolve("releng/org.rsaml.repository");
        Set<String> runtime = new TreeSet<>();
        Matcher m = bundle.matcher(Files.readString(site.resolve("category.xml")));
        while (m.find()) {
            runtime.add(m.group(1));
        }
        Set<String> full = new TreeSet<>();
        m = bundle.matcher(Files.readString(site.resolve("ide/category.xml")));
        while (m.find()) {
            full.add(m.group(1));
        }
        assertTrue(!runtime.isEmpty(), "category.xml lists the bundles the runtime needs");
        Set<String> missing = new TreeSet<>(runtime);
        missing.removeAll(full);
        assertEquals(Set.of(), missing, "bundles of releng/org.rsaml.repository/category.xml missing from ide/category.xml");
    }
}
