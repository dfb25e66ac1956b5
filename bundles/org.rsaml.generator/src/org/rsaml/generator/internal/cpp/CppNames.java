/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.cpp;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.rsaml.generator.internal.NameScope;
import org.rsaml.generator.internal.Names;
import org.rsaml.generator.internal.cxx.CxxNames;
import org.rsaml.analysis.plan.ExecutionPlan;
import org.rsaml.analysis.plan.LinkPlan;
import org.rsaml.analysis.plan.PlannedModule;
import org.rsaml.analysis.plan.PlannedPort;

/**
 * What only the C++ target names: the members of the generated architecture class, the data types
 * of the ports and the architect's message structs.
 */
public final class CppNames {

    /** A structured message type as a struct of the architect's, in {@code src/msg/}. */
    public static final class MessageStruct {
        public final String key;
        /** Fully qualified C++ name. */
        public final String cppName;
        /** Header path under {@code src/}. */
        public final String cppHeader;
        public final List<String> cppNamespaces = new ArrayList<>();
        public final String cppStruct;

        MessageStruct(String project, String key, NameScope scope) {
            this.key = key;
            String[] segments = key.split("/|::|\\.");
            List<String> path = new ArrayList<>();
            for (int i = 0; i < segments.length - 1; i++) {
                if (!segments[i].isBlank()) {
                    path.add(Names.identifier(segments[i]));
                }
            }
            String struct = Names.pascal(segments.length == 0 ? key : segments[segments.length - 1]);
            String prefix = path.isEmpty() ? "" : String.join("/", path) + "/";
            struct = scope.allocate(prefix + struct).substring(prefix.length());
            cppNamespaces.addAll(path);
            cppStruct = struct;
            cppName = "::" + project + "::msg::" + (path.isEmpty() ? "" : String.join("::", path) + "::") + struct;
            cppHeader = "msg/" + prefix + struct + ".hpp";
        }
    }

    private final Map<PlannedModule, String> members = new IdentityHashMap<>();
    private final Map<LinkPlan, String> linkMembers = new IdentityHashMap<>();
    private final Map<String, MessageStruct> structs = new LinkedHashMap<>();

    public CppNames(ExecutionPlan plan, CxxNames names) {
        NameScope scope = new NameScope(false, "system_", "run");
        for (PlannedModule m : plan.modules()) {
            members.put(m, scope.allocate(Names.stem(names.layerId(m) + "_" + names.nodeName(m)), "", "_"));
        }
        for (LinkPlan l : plan.links()) {
            linkMembers.put(l, scope.allocate(Names.stem("link_" + members.get(l.owner()) + "_" + l.link().getName()), "", "_"));
        }
        NameScope structScope = new NameScope(true);
        for (String key : plan.messageTypes()) {
            structs.put(key, new MessageStruct(names.project(), key, structScope));
        }
    }

    /** The module's member in the generated architecture class. */
    public String member(PlannedModule m) {
        return members.get(m);
    }

    public String member(LinkPlan l) {
        return linkMembers.get(l);
    }

    public List<MessageStruct> messageStructs() {
        return new ArrayList<>(structs.values());
    }

    /** The C++ type of a port's data. */
    public String cppType(PlannedPort p) {
        return switch (p.kind()) {
            case NUMERIC -> "double";
            case ALPHANUMERIC -> "std::string";
            case BOOLEAN -> "bool";
            case STRUCTURED -> structs.get(p.messageType()).cppName;
        };
    }
}
