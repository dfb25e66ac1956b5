/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.analysis.plan;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.rsaml.model.DataType;
import org.rsaml.model.EntryPort;
import org.rsaml.model.Port;
import org.rsaml.model.support.RsamlLabels;

public final class PlannedPort {
    final PlannedModule module;
    final Port port;
    final boolean entry;
    final String name;
    final String qualifiedName;
    final DataKind kind;
    final String messageType;
    final List<Flow> outgoing = new ArrayList<>();
    final List<Flow> incoming = new ArrayList<>();
    final List<LinkPlan> triggers = new ArrayList<>();
    final List<LinkPlan> inhibitors = new ArrayList<>();
    final List<LinkPlan> suppressors = new ArrayList<>();

    PlannedPort(ExecutionPlan plan, PlannedModule module, Port port) {
        this.module = module;
        this.port = port;
        this.entry = port instanceof EntryPort;
        this.name = RsamlLabels.name(port);
        this.qualifiedName = module.qualifiedName + "." + name;
        DataType type = port.getDataType() == null ? DataType.NUMERIC : port.getDataType();
        this.kind = switch (type) {
            case ALPHANUMERIC -> DataKind.ALPHANUMERIC;
            case BOOLEAN -> DataKind.BOOLEAN;
            case STRUCTURED -> DataKind.STRUCTURED;
            default -> DataKind.NUMERIC;
        };
        // Read as the rules read it (RSA-02, RSA-18): trimmed, and blank is missing.
        String written = port.normalizedMessageType();
        this.messageType = kind == DataKind.STRUCTURED ? (written == null ? "StructuredData" : written) : null;
    }

    boolean sameData(PlannedPort other) {
        return kind == other.kind && java.util.Objects.equals(messageType, other.messageType);
    }

    public PlannedModule module() {
        return module;
    }

    public Port port() {
        return port;
    }

    /** Whether it is an entry port (else an output port). */
    public boolean entry() {
        return entry;
    }

    public String name() {
        return name;
    }

    /** {@code layer/module.port}. */
    public String qualifiedName() {
        return qualifiedName;
    }

    public String description() {
        return port.getDescription();
    }

    public DataKind kind() {
        return kind;
    }

    /** The structured message type's name as written on the port (trimmed), or null. */
    public String messageType() {
        return messageType;
    }

    public List<Flow> outgoing() {
        return Collections.unmodifiableList(outgoing);
    }

    public List<Flow> incoming() {
        return Collections.unmodifiableList(incoming);
    }

    /** Links this port's messages trigger. */
    public List<LinkPlan> triggers() {
        return Collections.unmodifiableList(triggers);
    }

    /** Inhibitors that block this (output) port. */
    public List<LinkPlan> inhibitors() {
        return Collections.unmodifiableList(inhibitors);
    }

    /** Suppressors that replace what this (entry) port receives. */
    public List<LinkPlan> suppressors() {
        return Collections.unmodifiableList(suppressors);
    }

    /** {@code numeric data}, {@code structured data 'Pose'}, ... for messages. */
    public String dataLabel() {
        return kind == DataKind.STRUCTURED ? "structured data '" + messageType + "'"
                : kind.name().toLowerCase(java.util.Locale.ROOT) + " data";
    }
}
