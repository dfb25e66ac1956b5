package org.rsaml.codegen;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

class GeneratedCodeUpToDateTest {

    @Test
    void committedGeneratedCodeMatchesTheEcore() throws Exception {
        Path root = Path.of(System.getProperty("rsaml.root", "../..")).toAbsolutePath().normalize();
        List<String> stale = RsamlCodegen.check(root);
        assertEquals(List.of(), stale,
                "Generated code is out of date with rsaml.ecore. Regenerate it with "
                        + "./mvnw -Pregenerate -pl releng/org.rsaml.codegen process-classes");
    }
}
