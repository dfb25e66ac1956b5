/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.generator.internal.ros2;

import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;

import org.yaml.snakeyaml.LoaderOptions;
import org.yaml.snakeyaml.Yaml;
import org.yaml.snakeyaml.error.Mark;
import org.yaml.snakeyaml.error.MarkedYAMLException;
import org.yaml.snakeyaml.error.YAMLException;
import org.yaml.snakeyaml.nodes.MappingNode;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.NodeTuple;
import org.yaml.snakeyaml.nodes.ScalarNode;

/**
 * A ROS 2 parameters file as ROS 2 reads it, read with a YAML parser (SnakeYAML, composing the
 * document only: no object is constructed from it): node names mapped to {@code ros__parameters},
 * whose nested mappings are joined with dots ({@code rsaml: {simulated_load: 0.5}} is
 * {@code rsaml.simulated_load}); every parameter with its line.
 *
 * @param sections   the file's node sections, in order
 * @param parameters every parameter of every section, in order
 * @param error      why the file is not a parameters file ROS 2 takes, with its line; null when it is
 */
record Ros2ParamsFile(List<Section> sections, List<Parameter> parameters, Problem error) {

    /** A node's section: its name as written, without a leading slash, and its line (from 1). */
    record Section(String node, int line) {
    }

    /** A parameter of a node's section: its name (nested keys joined with dots), its value as written, its line. */
    record Parameter(String node, String name, String value, int line) {
    }

    /** What is wrong with the file, and on which line (from 1). */
    record Problem(int line, String message) {
    }

    /** Reads the text of a parameters file. */
    static Ros2ParamsFile read(String text) {
        List<Section> sections = new ArrayList<>();
        List<Parameter> parameters = new ArrayList<>();
        Node root;
        try {
            root = new Yaml(new LoaderOptions()).compose(new StringReader(text));
        } catch (MarkedYAMLException e) {
            Mark mark = e.getProblemMark() != null ? e.getProblemMark() : e.getContextMark();
            return new Ros2ParamsFile(sections, parameters, new Problem(mark == null ? 1 : mark.getLine() + 1,
                    "not YAML: " + (e.getProblem() == null ? e.getMessage() : e.getProblem())));
        } catch (YAMLException e) {
            return new Ros2ParamsFile(sections, parameters, new Problem(1, "not YAML: " + e.getMessage()));
        }
        if (root == null) {
            return new Ros2ParamsFile(sections, parameters, null);
        }
        if (!(root instanceof MappingNode nodes)) {
            return new Ros2ParamsFile(sections, parameters, new Problem(line(root), "a ROS 2 parameters file maps node names to their ros__parameters"));
        }
        for (NodeTuple t : nodes.getValue()) {
            String node = text(t.getKeyNode()).replaceFirst("^/", "");
            sections.add(new Section(node, line(t.getKeyNode())));
            if (t.getValueNode() instanceof MappingNode body) {
                for (NodeTuple b : body.getValue()) {
                    if ("ros__parameters".equals(text(b.getKeyNode())) && b.getValueNode() instanceof MappingNode values) {
                        flatten(node, "", values, parameters);
                    }
                }
            }
        }
        return new Ros2ParamsFile(sections, parameters, null);
    }

    private static void flatten(String node, String prefix, MappingNode mapping, List<Parameter> into) {
        for (NodeTuple t : mapping.getValue()) {
            String name = prefix + text(t.getKeyNode());
            if (t.getValueNode() instanceof MappingNode nested) {
                flatten(node, name + ".", nested, into);
            } else {
                into.add(new Parameter(node, name, text(t.getValueNode()), line(t.getKeyNode())));
            }
        }
    }

    /** A scalar's text; another node's YAML form, as a reader would see it. */
    private static String text(Node n) {
        return n instanceof ScalarNode s ? s.getValue() : n.getNodeId().name();
    }

    private static int line(Node n) {
        return n.getStartMark() == null ? 1 : n.getStartMark().getLine() + 1;
    }
}
