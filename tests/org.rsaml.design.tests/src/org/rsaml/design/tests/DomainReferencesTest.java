/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.rsaml.design.services.RsamlServices;

/** Every class, feature, navigation, literal and service that rsaml.odesign names exists in rsaml.ecore and RsamlServices, services taking what they are called on. */
class DomainReferencesTest {

    @Test
    void everyReferenceToRsamlExists() throws Exception {
        SiriusSpecifications.Loaded loaded = SiriusSpecifications.load(Repository.siriusMetamodels(),
                Repository.file(Repository.ECORE), Repository.file(Repository.ODESIGN));
        assertEquals(List.of(), DomainReferences.check(loaded, RsamlServices.class),
                "every class, feature and service rsaml.odesign names exists in RsaML");
    }

    @Test
    void everyBrokenReferenceIsReported() throws Exception {
        SiriusSpecifications.Loaded loaded = SiriusSpecifications.load(Repository.siriusMetamodels(),
                Repository.file(Repository.ECORE), Repository.resource("broken-domain-references.odesign"));
        assertEquals(List.of(), loaded.problems(), "the crafted specification is sound for Sirius; only its RsaML is wrong");
        String layer = "broken/Broken/Diagram/Default/LayerBox";
        String port = layer + "/PortNode";
        String predicate = "'aql:self.dataType = model::DataType::structural and self.oclIsKindOf(model::Prot)'";
        String tools = "broken/Broken/Diagram/Default/Tools";
        assertEquals(List.of(
                "broken/Broken/Diagram/Default/ConnectionEdge sourceFinderExpression: 'aql:self.source.module' yields Module,"
                        + " which none of its mappings shows ([Port])",
                "broken/Broken/Diagram/Default/ConnectionEdge targetFinderExpression: 'feature:targt': Connection has no feature 'targt'",
                layer + "/FlatContainerStyleDescription labelExpression: 'feature:nam': Layer has no feature 'nam'",
                layer + "/FlatContainerStyleDescription tooltipExpression: 'aql:self.name.rsamlLabel()' calls 'rsamlLabel' on EString,"
                        + " which no method 'rsamlLabel' of the viewpoint's Java services takes",
                port + "/ConditionalNodeStyleDescription predicateExpression: " + predicate + ": DataType has no literal 'structural'",
                port + "/ConditionalNodeStyleDescription predicateExpression: " + predicate + ": rsaml.ecore has no classifier 'Prot'",
                port + "/SquareDescription labelExpression: 'aql:self.module.layer.levle': Layer has no feature 'levle'",
                port + "/SquareDescription labelExpression: 'aql:self.rsamlLable()' calls 'rsamlLable', which is neither"
                        + " an AQL service nor a method of the viewpoint's Java services",
                port + "/SquareDescription tooltipExpression: 'aql:self.dataType.name' navigates to 'name' from a DataType value,"
                        + " which has no features",
                "broken/Broken/Diagram/Default/ModuleBox domainClass: 'model.Modul' is not a class of rsaml.ecore",
                "broken/Broken/Diagram/Default/ModuleBox semanticCandidatesExpression: 'aql:self.layers.modules.functions.ports':"
                        + " Function has no feature 'ports'",
                tools + "/createConnection/SetValue: 'source' takes OutputPort, but 'var:target' is a Port",
                tools + "/createLayer/ChangeContext browseExpression: 'var:containr' names no variable known there ([container, self])",
                tools + "/createLayer/ChangeContext: cannot tell which RsaML class 'var:containr' leads to, so the operations"
                        + " inside are not checked",
                tools + "/createModule/CreateInstance referenceName: Architecture has no feature 'layer'",
                tools + "/createModule/CreateInstance: 'layers' holds Layer elements, not RealTimeElement",
                tools + "/createModule/CreateInstance: 'model.RealTimeElement' is abstract and cannot be created",
                tools + "/createModule/SetValue featureName: Module has no feature 'lvl'",
                "broken/Broken/Diagram/Default/errors domainClass: 'rsaml.NamedElement' names package 'rsaml',"
                        + " but rsaml.ecore's package is called 'model'"),
                DomainReferences.check(loaded, RsamlServices.class), "each wrong name of the specification is reported with its place");
    }
}
