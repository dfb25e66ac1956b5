/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.text.validation;

import java.nio.file.Path;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.util.IAcceptor;
import org.eclipse.xtext.util.LineAndColumn;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.Issue;
import org.eclipse.xtext.validation.ResourceValidatorImpl;
import org.rsaml.model.Architecture;
import org.rsaml.model.RsamlPackage;
import org.rsaml.text.resource.RsamlTextResource;
import org.rsaml.validation.Finding;
import org.rsaml.validation.LoadedModel;
import org.rsaml.validation.RsamlModelValidator;

/**
 * The problems an editor or the language server shows for a textual model: its syntax and reference
 * errors, then, when there are none, exactly the findings {@code rsaml validate} reports (rule id as
 * the issue's code, severity, message), each over its element's keyword and name.
 */
public class RsamlTextResourceValidator extends ResourceValidatorImpl {

    @Override
    protected void validate(Resource resource, CheckMode mode, CancelIndicator monitor, IAcceptor<Issue> acceptor) {
        if (!(resource instanceof RsamlTextResource text) || !resource.getErrors().isEmpty() || resource.getContents().isEmpty()
                || !(resource.getContents().get(0) instanceof Architecture)) {
            return;
        }
        Path path = resource.getURI().isFile() ? Path.of(resource.getURI().toFileString()) : null;
        String file = path != null ? path.getFileName().toString() : resource.getURI().lastSegment();
        for (Finding finding : RsamlModelValidator.validate(LoadedModel.of(text, file, path))) {
            if (monitor.isCanceled()) {
                return;
            }
            acceptor.accept(issue(resource, finding));
        }
    }

    private static Issue issue(Resource resource, Finding finding) {
        Issue.IssueImpl issue = new Issue.IssueImpl();
        issue.setCode(finding.ruleId());
        issue.setMessage(finding.message());
        issue.setSeverity(switch (finding.severity()) {
            case ERROR -> Severity.ERROR;
            case WARNING -> Severity.WARNING;
            default -> Severity.INFO;
        });
        issue.setType(org.eclipse.xtext.validation.CheckType.FAST);
        EObject element = finding.uriFragment() == null ? null : resource.getEObject(finding.uriFragment());
        ICompositeNode node = element == null ? null : NodeModelUtils.getNode(element);
        if (node == null) {
            issue.setLineNumber(Math.max(1, finding.line()));
            issue.setColumn(Math.max(1, finding.column()));
            issue.setOffset(0);
            issue.setLength(0);
            return issue;
        }
        int start = node.getOffset();
        int end = headEnd(element, node);
        LineAndColumn from = NodeModelUtils.getLineAndColumn(node, start);
        LineAndColumn to = NodeModelUtils.getLineAndColumn(node, end);
        issue.setOffset(start);
        issue.setLength(end - start);
        issue.setLineNumber(from.getLine());
        issue.setColumn(from.getColumn());
        issue.setLineNumberEnd(to.getLine());
        issue.setColumnEnd(to.getColumn());
        issue.setUriToProblem(resource.getURI().appendFragment(finding.uriFragment()));
        return issue;
    }

    /** Where the element's head ends: after its name, or its first line for an element without one. */
    private static int headEnd(EObject element, ICompositeNode node) {
        for (INode name : NodeModelUtils.findNodesForFeature(element, RsamlPackage.Literals.NAMED_ELEMENT__NAME)) {
            return name.getEndOffset();
        }
        String text = node.getText();
        int lead = node.getOffset() - node.getTotalOffset();
        int newline = text.indexOf('\n', lead);
        return newline < 0 ? node.getEndOffset() : node.getTotalOffset() + newline;
    }
}
