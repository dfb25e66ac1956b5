package org.rsaml.it.tycho;

/** Stands for the code that implements the modeled architecture. */
public final class Robot {
    private Robot() {
    }
}
