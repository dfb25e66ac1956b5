/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.diagram.internal;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.elk.core.math.KVector;
import org.eclipse.elk.core.options.CoreOptions;
import org.eclipse.elk.core.options.Direction;
import org.eclipse.elk.core.options.SizeConstraint;
import org.eclipse.elk.graph.ElkConnectableShape;
import org.eclipse.elk.graph.ElkEdge;
import org.eclipse.elk.graph.ElkNode;
import org.eclipse.elk.graph.ElkShape;
import org.eclipse.emf.ecore.EObject;
import org.rsaml.diagram.DiagramOverlay;
import org.rsaml.model.Activity;
import org.rsaml.model.Architecture;
import org.rsaml.model.Goal;
import org.rsaml.model.Mission;
import org.rsaml.model.Order;
import org.rsaml.model.Plan;
import org.rsaml.model.Supervisor;
import org.rsaml.model.support.RsamlLabels;
import org.rsaml.validation.Finding;

/**
 * The mission view: each mission as a container of its goals (sub-goals linked to their goal) and
 * its plans (with their activities in order, linked to the goals they achieve); supervisors
 * linked to the plans they control, orders to the activity they request.
 */
public final class MissionLayout extends Layout {

    private final List<Goal> goals = new ArrayList<>();

    public MissionLayout(Architecture architecture, List<Finding> findings, DiagramOverlay.Notes notes) {
        super(architecture, "mission", findings, notes);
    }

    public static Drawing draw(Architecture architecture, List<Finding> findings, DiagramOverlay.Notes notes) {
        return new MissionLayout(architecture, findings, notes).run();
    }

    @Override
    boolean draws(EObject element) {
        return element instanceof Architecture || element instanceof Mission || element instanceof Goal
                || element instanceof Plan || element instanceof Activity || element instanceof Supervisor
                || element instanceof Order;
    }

    private List<Line> title() {
        List<Line> lines = new ArrayList<>();
        lines.add(new Line(RsamlLabels.name(architecture) + " (missions)", TITLE + 2, true, "title"));
        boolean empty = architecture.getMissions().isEmpty() && architecture.getSupervisors().isEmpty() && architecture.getOrders().isEmpty();
        lines.add(new Line(empty ? "no missions, supervisors or orders in this model"
                : architecture.getMissions().size() + " missions, " + architecture.getSupervisors().size()
                + " supervisors, " + architecture.getOrders().size() + " orders", BODY, false, "subtitle"));
        lines.addAll(overlayLines(architecture));
        return lines;
    }

    private List<Line> lines(EObject element) {
        List<Line> lines = new ArrayList<>();
        if (element instanceof Mission mission) {
            lines.add(new Line("mission " + RsamlLabels.name(mission), TITLE, true, "title"));
        } else if (element instanceof Goal goal) {
            lines.add(new Line(RsamlLabels.name(goal), BODY, true, "title"));
            lines.add(new Line("priority " + goal.getPriority(), SMALL, false, "timing"));
        } else if (element instanceof Plan plan) {
            lines.add(new Line("plan " + RsamlLabels.name(plan), BODY, true, "title"));
        } else if (element instanceof Activity activity) {
            lines.add(new Line(RsamlLabels.name(activity), BODY, false, "title"));
            lines.add(new Line(RsamlLabels.timingFacts(activity), SMALL, false, "timing"));
        } else if (element instanceof Supervisor supervisor) {
            lines.add(new Line("supervisor " + RsamlLabels.name(supervisor), BODY, true, "title"));
            if (supervisor.getRealisedBy() != null) {
                lines.add(new Line("realised by " + RsamlLabels.name(supervisor.getRealisedBy()), SMALL, false, "timing"));
            }
        } else if (element instanceof Order order) {
            lines.add(new Line("order " + RsamlLabels.name(order), BODY, true, "title"));
            String from = order.getIssuer() == null || order.getIssuer().isEmpty() ? "" : "from " + order.getIssuer();
            String to = order.getReceiver() == null ? "" : "to " + RsamlLabels.name(order.getReceiver());
            if (!(from + to).isEmpty()) {
                lines.add(new Line((from + " " + to).trim(), SMALL, false, "timing"));
            }
        }
        lines.addAll(overlayLines(element));
        return lines;
    }

    private double textWidth(EObject element) {
        List<Line> lines = lines(element);
        double badge = badgeWidth(badgeText(element));
        return Math.max(lines.get(0).width() + (badge > 0 ? badge + 4 : 0), width(lines));
    }

    private ElkNode leaf(ElkNode parent, EObject element, boolean ellipse) {
        List<Line> lines = lines(element);
        double w = textWidth(element) + 2 * PAD + 4;
        double h = height(lines) + 2 * PAD;
        if (ellipse) {
            // The text box is inscribed in the ellipse: scale both axes by the square root of two.
            w = w * Math.sqrt(2);
            h = h * Math.sqrt(2);
        }
        return node(parent, element, w, h);
    }

    private ElkNode container(ElkNode parent, EObject element) {
        List<Line> lines = lines(element);
        double w = textWidth(element) + 2 * PAD + 16;
        ElkNode node = node(parent, element, w, height(lines) + 2 * PAD);
        node.setProperty(CoreOptions.DIRECTION, Direction.RIGHT);
        node.setProperty(CoreOptions.NODE_SIZE_CONSTRAINTS, SizeConstraint.minimumSize());
        node.setProperty(CoreOptions.NODE_SIZE_MINIMUM, new KVector(Math.ceil(w), Math.ceil(height(lines) + 2 * PAD + 20)));
        padding(node, height(lines) + 2 * PAD + 4, 12);
        spacing(node);
        return node;
    }

    @Override
    void build() {
        root.setProperty(CoreOptions.DIRECTION, Direction.RIGHT);
        List<Line> title = title();
        padding(root, PAD * 2 + height(title), 16);
        root.setProperty(CoreOptions.NODE_SIZE_CONSTRAINTS, SizeConstraint.minimumSize());
        root.setProperty(CoreOptions.NODE_SIZE_MINIMUM, new KVector(Math.ceil(width(title) + badgeWidth(badgeText(architecture)) + 40), 0));
        map(root, architecture);
        for (Supervisor supervisor : architecture.getSupervisors()) {
            leaf(root, supervisor, false);
        }
        for (Order order : architecture.getOrders()) {
            leaf(root, order, false);
        }
        for (Mission mission : architecture.getMissions()) {
            ElkNode node = container(root, mission);
            for (Plan plan : mission.getPlans()) {
                ElkNode planNode = container(node, plan);
                for (Activity activity : plan.getActivities()) {
                    leaf(planNode, activity, false);
                }
            }
            for (Goal goal : mission.getGoals()) {
                goal(node, goal);
            }
        }
        for (Goal goal : goals) {
            for (Goal sub : goal.getSubGoals()) {
                edge(connectable(goal), connectable(sub));
            }
        }
        for (Mission mission : architecture.getMissions()) {
            for (Plan plan : mission.getPlans()) {
                for (Goal goal : plan.getAchieves()) {
                    if (connectable(goal) != null) {
                        label(edge(connectable(plan), connectable(goal)), "achieves", SMALL, false);
                    }
                }
            }
        }
        for (Supervisor supervisor : architecture.getSupervisors()) {
            for (Plan plan : supervisor.getPlans()) {
                if (connectable(plan) != null) {
                    label(edge(connectable(supervisor), connectable(plan)), "controls", SMALL, false);
                }
            }
        }
        for (Order order : architecture.getOrders()) {
            if (order.getRequests() != null && connectable(order.getRequests()) != null) {
                label(edge(connectable(order), connectable(order.getRequests())), "requests", SMALL, false);
            }
        }
    }

    private void goal(ElkNode mission, Goal goal) {
        leaf(mission, goal, true);
        goals.add(goal);
        for (Goal sub : goal.getSubGoals()) {
            goal(mission, sub);
        }
    }

    private ElkConnectableShape connectable(EObject element) {
        return (ElkConnectableShape) shapeOf.get(element);
    }

    @Override
    void collect() {
        Drawing.Shape frame = shape("architecture", root, null);
        frame.form = "round";
        List<Line> title = title();
        place(frame.texts, title, frame.x + 16, frame.y + PAD, "start");
        addBadge(frame, frame.x + 16 + title.get(0).width() + 8, frame.y + PAD);
        for (Mission mission : architecture.getMissions()) {
            Drawing.Shape m = node("mission", mission, frame, "round");
            for (Plan plan : mission.getPlans()) {
                Drawing.Shape p = node("plan", plan, m, "round");
                for (Activity activity : plan.getActivities()) {
                    node("activity", activity, p, "rect");
                }
            }
            for (Goal goal : goals) {
                if (goal.getMission() == mission || isBelow(goal, mission)) {
                    node("goal", goal, m, "ellipse");
                }
            }
        }
        for (Supervisor supervisor : architecture.getSupervisors()) {
            node("supervisor", supervisor, frame, "rect");
        }
        for (Order order : architecture.getOrders()) {
            node("order", order, frame, "rect");
        }
        for (ElkEdge edge : ArchitectureLayout.allEdges(root)) {
            EObject source = elementOf.get(edge.getSources().get(0));
            EObject target = elementOf.get(edge.getTargets().get(0));
            String kind = source instanceof Goal ? "subgoal" : source instanceof Plan ? "achieves"
                    : source instanceof Supervisor ? "controls" : "requests";
            link(kind, edge, null, source, target, null);
        }
    }

    private static boolean isBelow(Goal goal, Mission mission) {
        for (EObject e = goal; e != null; e = e.eContainer()) {
            if (e == mission) {
                return true;
            }
        }
        return false;
    }

    private Drawing.Shape node(String kind, EObject element, Drawing.Shape parent, String form) {
        Drawing.Shape shape = shape(kind, (ElkShape) shapeOf.get(element), parent);
        shape.form = form;
        List<Line> lines = lines(element);
        boolean ellipse = form.equals("ellipse");
        double textWidth = textWidth(element);
        double x = ellipse ? shape.x + (shape.width - textWidth) / 2 : shape.x + PAD + 2;
        double y = ellipse ? shape.y + (shape.height - height(lines)) / 2 : shape.y + PAD;
        place(shape.texts, lines, x, y, "start");
        addBadge(shape, x + lines.get(0).width() + 4, y);
        return shape;
    }
}
