/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.model.support;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import org.rsaml.model.Architecture;
import org.rsaml.model.Layer;
import org.rsaml.model.Module;
import org.rsaml.model.Port;

/**
 * The names the generated code and ROS 2 give an architecture's layers, modules and ports ({@link Ids}),
 * made here once for the generators and for the rule that checks ROS 2 topics (RSA-28), which must know
 * the default topics ({@code <layer>/<node>/<port>}) the generated nodes use.
 */
public final class RsamlNames {

    /** The last segment of a managed node's topic of transitions ({@link RosNodes#transitionEventTopic}). */
    public static final String TRANSITION_EVENT = "transition_event";

    private RsamlNames() {
    }

    /** C++17 keywords and alternative tokens, and names the generated code or common headers take. */
    private static final Set<String> CPP_RESERVED = Set.of("alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand",
            "bitor", "bool", "break", "case", "catch", "char", "char8_t", "char16_t", "char32_t", "class", "compl",
            "concept", "const", "consteval", "constexpr", "constinit", "const_cast", "continue", "co_await",
            "co_return", "co_yield", "decltype", "default", "delete", "do", "double", "dynamic_cast", "else", "enum",
            "explicit", "export", "extern", "false", "float", "for", "friend", "goto", "if", "inline", "int", "long",
            "mutable", "namespace", "new", "noexcept", "not", "not_eq", "nullptr", "operator", "or", "or_eq",
            "private", "protected", "public", "register", "reinterpret_cast", "requires", "return", "short",
            "signed", "sizeof", "static", "static_assert", "static_cast", "struct", "switch", "template", "this",
            "thread_local", "throw", "true", "try", "typedef", "typeid", "typename", "union", "unsigned", "using",
            "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq", "final", "override", "import",
            "module",
            // Macros of the C library and of GCC's GNU modes, and namespaces the generated code uses.
            "NULL", "EOF", "assert", "errno", "stdin", "stdout", "stderr", "linux", "unix", "i386", "main", "std",
            "rsaml", "rclcpp", "msg");

    /** Python keywords and soft keywords (launch files). */
    private static final Set<String> PYTHON_RESERVED = Set.of("False", "None", "True", "and", "as", "assert", "async",
            "await", "break", "class", "continue", "def", "del", "elif", "else", "except", "finally", "for", "from",
            "global", "if", "import", "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return", "try",
            "while", "with", "yield", "match", "case", "type");

    /** Device names Windows refuses as file names, whatever the extension. */
    private static final Set<String> WINDOWS_DEVICES = Set.of("con", "prn", "aux", "nul", "com1", "com2", "com3",
            "com4", "com5", "com6", "com7", "com8", "com9", "lpt1", "lpt2", "lpt3", "lpt4", "lpt5", "lpt6", "lpt7",
            "lpt8", "lpt9");

    /** {@code eMoveSP} to {@code e_move_sp}: for ROS package, node, executable and topic names. */
    public static String snake(String raw) {
        List<String> words = RsamlPackages.words(raw);
        String s = words.isEmpty() ? "unnamed" : String.join("_", words).toLowerCase(Locale.ROOT);
        if (Character.isDigit(s.charAt(0))) {
            s = "n" + s;
        }
        return reserved(s) ? s + "_" : s;
    }

    /**
     * A name as a file name stem and the like: every character but an ASCII letter or digit becomes an
     * underscore, runs of underscores collapse, leading and trailing underscores go, and a leading
     * digit gets an {@code n} before it; {@code unnamed} when nothing is left. Reserved words are kept.
     */
    public static String stem(String raw) {
        String s = collapse(raw);
        if (s.isEmpty()) {
            return "unnamed";
        }
        return Character.isDigit(s.charAt(0)) ? "n" + s : s;
    }

    /**
     * Every character but an ASCII letter or digit an underscore, runs of underscores collapsed,
     * leading and trailing underscores gone (C++ reserves {@code __} and {@code _X}); possibly empty.
     */
    public static String collapse(String raw) {
        if (raw == null) {
            return "";
        }
        StringBuilder out = new StringBuilder(raw.length());
        for (int i = 0; i < raw.length(); i++) {
            char c = raw.charAt(i);
            boolean ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
            if (ok) {
                out.append(c);
            } else if (out.length() > 0 && out.charAt(out.length() - 1) != '_') {
                out.append('_');
            }
        }
        int end = out.length();
        while (end > 0 && out.charAt(end - 1) == '_') {
            end--;
        }
        return out.substring(0, end);
    }

    /** Whether a name may not be used as it is in generated code or as a file name. */
    public static boolean reserved(String s) {
        return CPP_RESERVED.contains(s) || PYTHON_RESERVED.contains(s) || WINDOWS_DEVICES.contains(s.toLowerCase(Locale.ROOT));
    }

    /**
     * The names taken in one scope (a namespace, a class, a folder). Names are handed out in model
     * order, so the first element keeps its sanitised name and a later one that collides with it
     * gets the first free suffix {@code _2}, {@code _3}, ...: the same model always gives the same
     * names. Folder and file scopes compare without case, for case-insensitive file systems.
     */
    public static class Scope {

        private final Set<String> taken = new HashSet<>();
        private final boolean ignoreCase;

        public Scope(boolean ignoreCase, String... reserved) {
            this.ignoreCase = ignoreCase;
            for (String r : reserved) {
                taken.add(key(r));
            }
        }

        /** Takes {@code preferred}, or the first free {@code preferred_N}. */
        public String allocate(String preferred) {
            return allocate(preferred, "");
        }

        /**
         * Takes a name {@code n} such that {@code prefix + n + suffix} is free for every given
         * pair, and reserves all of them: for a port that becomes {@code in_x} and {@code on_x}, or a
         * class {@code X} that also needs {@code XBase}.
         *
         * @param affixes alternating prefix and suffix strings; {@code ""} for none
         */
        public String allocate(String preferred, String... affixes) {
            Interruptions.check(); // one name per element of an architecture-wide table: a stopped command ends here
            String[] pairs = affixes.length == 0 || (affixes.length == 1 && affixes[0].isEmpty()) ? new String[] { "", "" } : affixes;
            if (pairs.length % 2 != 0) {
                pairs = java.util.Arrays.copyOf(pairs, pairs.length + 1);
                pairs[pairs.length - 1] = "";
            }
            for (int n = 1;; n++) {
                String candidate = n == 1 ? preferred : preferred + "_" + n;
                boolean free = true;
                for (int i = 0; i < pairs.length && free; i += 2) {
                    free = !taken.contains(key(pairs[i] + candidate + pairs[i + 1]));
                }
                if (free) {
                    for (int i = 0; i < pairs.length; i += 2) {
                        taken.add(key(pairs[i] + candidate + pairs[i + 1]));
                    }
                    return candidate;
                }
            }
        }

        public boolean isTaken(String name) {
            return taken.contains(key(name));
        }

        private String key(String name) {
            return ignoreCase ? name.toLowerCase(Locale.ROOT) : name;
        }
    }

    /**
     * An architecture's layer ids (folders and C++ namespaces: not the generated tree's own folder
     * names), node names (unique in their layer) and port segments (unique in their module), allocated in
     * model order; and its ports in the order the generators take them (layers by level, model order
     * within a level).
     */
    public static final class Ids {

        private static final String[] FOLDERS = { "rsaml", "msg", "gen", "src", "launch", "include", "build", "architecture",
                "messages", "main", "user" };

        private final Map<Layer, String> layers = new IdentityHashMap<>();
        private final Map<Module, String> nodes = new IdentityHashMap<>();
        private final Map<Port, String> ports = new IdentityHashMap<>();
        private final List<Port> ordered = new ArrayList<>();
        private final List<Module> modules = new ArrayList<>();
        private final String architectureName;

        public Ids(Architecture architecture) {
            architectureName = architecture.getName();
            Scope layerScope = new Scope(true, FOLDERS);
            for (Layer l : architecture.getLayers()) {
                layers.put(l, layerScope.allocate(snake(l.getName())));
            }
            List<Layer> byLevel = new ArrayList<>(architecture.getLayers());
            byLevel.sort(Comparator.comparingInt(Layer::getLevel)); // stable: model order within a level
            Map<Layer, Scope> nodeScopes = new HashMap<>();
            for (Layer l : byLevel) {
                for (Module m : l.getModules()) {
                    nodes.put(m, nodeScopes.computeIfAbsent(l, k -> new Scope(false)).allocate(snake(m.getName())));
                    modules.add(m);
                    Scope segments = new Scope(false);
                    for (Port p : m.getPorts()) {
                        ports.put(p, segments.allocate(snake(p.getName())));
                        ordered.add(p);
                    }
                }
            }
        }

        /** The layer's id: a folder and a C++ namespace. */
        public String layer(Layer l) {
            return layers.get(l);
        }

        /** The module's node name, unique in its layer. */
        public String node(Module m) {
            return nodes.get(m);
        }

        /**
         * The module's ROS 2 node name, unique in the architecture since every node runs in the launch's
         * one namespace: {@code <layer>_<node>} (the ROS 2 generator adds a suffix only where two such
         * names, or one and a container's, would clash).
         */
        public String rosNode(Module m) {
            return layers.get(m.getLayer()) + "_" + nodes.get(m);
        }

        /** Every module, layers by level, modules in model order. */
        public List<Module> modules() {
            return modules;
        }

        /** The architecture's name as the model gives it. */
        public String architectureName() {
            return architectureName;
        }

        /** The topic a port's node uses when the port names none and no port connected to it does: {@code <layer>/<node>/<port>}. */
        public String defaultTopic(Port p) {
            return layers.get(p.getModule().getLayer()) + "/" + nodes.get(p.getModule()) + "/" + ports.get(p);
        }

        /** Every port, layers by level, modules and ports in model order. */
        public List<Port> ports() {
            return ordered;
        }
    }

    /**
     * The names of the ROS 2 nodes the generated code gives the modules, which are also the names of
     * their executables: each module's {@link Ids#rosNode} as a file name stem, in one scope (without
     * case, as file names) that holds the ROS package's name first; a node whose name would clash, with
     * another or with the package's, gets the first free suffix {@code _2}, {@code _3}, ... (in
     * {@link Ids#modules} order). The ROS 2 generator takes its node names, executables and containers
     * from this scope; RSA-28 checks the managed nodes' {@code transition_event} topics with it.
     */
    public static final class RosNodes {

        private final Scope scope;
        private final Map<Module, String> names = new IdentityHashMap<>();

        /** The nodes of an architecture whose nodes are in ROS package {@code rosPackage}. */
        public RosNodes(Ids ids, String rosPackage) {
            scope = new Scope(true, rosPackage);
            for (Module m : ids.modules()) {
                names.put(m, scope.allocate(stem(ids.rosNode(m))));
            }
        }

        /** The module's node name in the generated code (and its executable's name). */
        public String of(Module m) {
            return names.get(m);
        }

        /**
         * The topic on which ROS 2 publishes the transitions of a managed (lifecycle) module's node,
         * {@code <node>/transition_event} (rclcpp_lifecycle's {@code ~/transition_event}, as
         * lifecycle_msgs/msg/TransitionEvent), relative to the launch's namespace as the ports' topics are.
         */
        public String transitionEventTopic(Module m) {
            return of(m) + "/" + TRANSITION_EVENT;
        }

        /** The scope of the names, for the generated code's other executables and nodes (containers, the lifecycle manager). */
        public Scope scope() {
            return scope;
        }
    }
}
