/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.design.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.rsaml.design.tests.SiriusSpecifications.get;
import static org.rsaml.design.tests.SiriusSpecifications.list;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.Test;

/** rsaml.odesign is an instance of Sirius 7.6's metamodel, as Sirius would read it: nothing unknown, dangling or missing. */
class SpecificationTest {

    @Test
    void rsamlOdesignIsAValidSiriusSpecification() throws Exception {
        SiriusSpecifications.Loaded loaded = SiriusSpecifications.load(Repository.siriusMetamodels(),
                Repository.file(Repository.ECORE), Repository.file(Repository.ODESIGN));
        assertEquals(List.of(), loaded.problems(), "Sirius reads rsaml.odesign without an unknown, dangling or missing value");

        EObject viewpoint = list(loaded.group(), "ownedViewpoints").get(0);
        assertEquals("rsaml", get(viewpoint, "modelFileExtension"), "the viewpoint applies to .rsaml files");
        assertEquals(List.of("Architecture", "Missions"),
                list(viewpoint, "ownedRepresentations").stream().map(r -> get(r, "name")).toList(),
                "the user can create an Architecture and a Missions diagram");
        for (EObject representation : list(viewpoint, "ownedRepresentations")) {
            assertEquals(List.of(loaded.rsaml()), list(representation, "metamodel"),
                    get(representation, "name") + " declares rsaml.ecore as its metamodel");
        }
    }

    @Test
    void unknownClassesAndFeaturesDanglingReferencesAndMissingValuesAreReported() throws Exception {
        SiriusSpecifications.Loaded loaded = SiriusSpecifications.load(Repository.siriusMetamodels(),
                Repository.file(Repository.ECORE), Repository.resource("broken-structure.odesign"));
        String edge = "broken/Broken/Diagram/Default/Edge";
        assertEquals(List.of(
                "error at 12:106: Feature 'domainClas' not found.",
                "error at 19:53: Class 'SquareDescriptio' is not found or is abstract.",
                "error at 7:336: Unresolved reference '//@ownedViewpoints[name='Broken']/@ownedRepresentations[name='Diagram']"
                        + "/@defaultLayer/@nodeMappings[name='Missing']'.",
                "unresolved reference " + edge + "/EdgeStyleDescription.strokeColor -> "
                        + "environment:/viewpoint#//@systemColors/@entries[name='blak']",
                "invalid: The required feature 'domainClass' of 'broken/Broken/Diagram/Default/Node' must be set",
                "invalid: The required feature 'labelColor' of 'broken/Broken/Diagram/Default/Node/SquareDescription' must be set",
                "invalid: The feature 'sourceMapping' of '" + edge + "' with 0 values must have at least 1 values",
                "invalid: The feature 'strokeColor' of '" + edge + "/EdgeStyleDescription' contains an unresolved proxy 'SystemColor'"),
                loaded.problems(), "each mistake of the broken specification is reported with its place");
    }
}
