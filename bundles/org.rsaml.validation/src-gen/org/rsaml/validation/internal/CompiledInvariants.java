/*
 * Copyright (c) 2026 RsaML contributors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rsaml.validation.internal;

import static org.rsaml.validation.internal.CompiledOcl.*;

import org.eclipse.emf.ecore.EObject;

/**
 * The OCL invariants of rsaml.ecore as Java, written by releng/org.rsaml.codegen (OclToJava) from their text in
 * the .ecore: do not edit; regenerate with
 * ./mvnw -Pregenerate -pl releng/org.rsaml.codegen,releng/org.rsaml.docgen -am process-classes
 */
final class CompiledInvariants {

    private CompiledInvariants() {
    }

    /** Class, constraint and OCL text of each compiled invariant; its index is its number in {@link #check}. */
    private static final String[][] COMPILED = {
        { "NamedElement", "RSA21_fileNameLength", "(normalizedName() = null or normalizedName().size() <= 100) and (oclIsKindOf(Port) implies (oclAsType(Port).normalizedMessageType() = null or oclAsType(Port).normalizedMessageType().size() <= 100))" },
        { "RealTimeElement", "RSA10_executionWithinPeriod", "(execType = ExecutionType::periodic and period > 0) implies execDuration <= period" },
        { "RealTimeElement", "RSA11_deadlineWithinPeriod", "(execType = ExecutionType::periodic and period > 0 and delay > 0) implies delay <= period" },
        { "RealTimeElement", "RSA12_periodicHasPeriod", "execType = ExecutionType::periodic implies period > 0" },
        { "RealTimeElement", "RSA13_nonNegativeTimes", "period >= 0 and delay >= 0 and execDuration >= 0" },
        { "RealTimeElement", "RSA17_executionWithinDeadline", "(type = ElementType::realTime and delay > 0) implies execDuration <= delay" },
        { "RealTimeElement", "RSA20_representableTimes", "representablePeriod(period) and representable(delay) and representable(execDuration)" },
        { "Architecture", "RSA01_declaredLayerCount", "declaredLayers = layers->size()" },
        { "Architecture", "RSA09_uniqueNames", "layers->isUnique(normalizedName()) and sensors->isUnique(normalizedName()) and actuators->isUnique(normalizedName()) and missions->isUnique(normalizedName()) and supervisors->isUnique(normalizedName()) and orders->isUnique(normalizedName()) and databases->isUnique(normalizedName())" },
        { "Architecture", "RSA14_layerLevels", "layers->isUnique(level) and layers->forAll(l | l.level >= 0 and l.level < layers->size())" },
        { "Layer", "RSA09_uniqueNames", "modules->isUnique(normalizedName())" },
        { "Layer", "RSA13_nonNegativeTimes", "maxExecTime >= 0" },
        { "Layer", "RSA20_representableTimes", "representable(maxExecTime)" },
        { "Layer", "RSA29_packageNameUsable", "packageProblem() = null" },
        { "Module", "RSA05_realTimeModuleTiming", "type = ElementType::realTime implies (period > 0 and delay > 0)" },
        { "Module", "RSA06_realTimeModuleFunctions", "type = ElementType::realTime implies functions->forAll(f | f.type = ElementType::realTime)" },
        { "Module", "RSA08_layerExecutionBudget", "(layer <> null and layer.maxExecTime > 0) implies compareTime(execDuration, layer, layer.maxExecTime) <= 0" },
        { "Module", "RSA09_uniqueNames", "ports->isUnique(normalizedName()) and functions->isUnique(normalizedName()) and inhibitors->isUnique(normalizedName()) and suppressors->isUnique(normalizedName())" },
        { "Function", "RSA07_realTimeFunctionActions", "type = ElementType::realTime implies actions->forAll(a | a.type = ElementType::realTime)" },
        { "Function", "RSA09_uniqueNames", "actions->isUnique(normalizedName())" },
        { "Function", "RSA27_functionWithinBudget", "(module <> null and module.execDuration > 0 implies compareTime(execDuration, module, module.execDuration) <= 0) and ((module <> null and module.layer <> null and module.layer.maxExecTime > 0) implies compareTime(execDuration, module.layer, module.layer.maxExecTime) <= 0)" },
        { "Action", "RSA27_actionWithinBudget", "(function <> null and function.execDuration > 0 implies compareTime(execDuration, function, function.execDuration) <= 0) and ((function <> null and function.module <> null and function.module.execDuration > 0) implies compareTime(execDuration, function.module, function.module.execDuration) <= 0) and ((function <> null and function.module <> null and function.module.layer <> null and function.module.layer.maxExecTime > 0) implies compareTime(execDuration, function.module.layer, function.module.layer.maxExecTime) <= 0)" },
        { "RTAction", "RSA15_rtActionIsRealTime", "type = ElementType::realTime" },
        { "Port", "RSA18_structuredPortNamesMessageType", "dataType = DataType::structured implies normalizedMessageType() <> null" },
        { "Port", "RSA28_topicNameUsable", "topicProblem() = null" },
        { "Connection", "RSA02_connectedPortTypes", "(source <> null and target <> null) implies (source.dataType = target.dataType and (source.dataType = DataType::structured implies source.normalizedMessageType() = target.normalizedMessageType()))" },
        { "Connection", "RSA03_adjacentLayerCommunication", "let from : Layer = if source = null or source.module = null then null else source.module.layer endif, to : Layer = if target = null or target.module = null then null else target.module.layer endif in (from <> null and to <> null) implies (from.level - to.level).abs() <= 1" },
        { "SubsumptionLink", "RSA13_nonNegativeTimes", "duration >= 0" },
        { "SubsumptionLink", "RSA20_representableTimes", "representable(duration)" },
        { "SubsumptionLink", "RSA26_durationBelowTriggerPeriod", "(trigger <> null and trigger.module <> null and duration > 0) implies (((trigger.module.execType = ExecutionType::periodic and trigger.module.period > 0) and (trigger.module.functions->exists(f | not (f.execType = ExecutionType::periodic and f.period > 0)) or not trigger.module.functions->exists(f | (f.execType = ExecutionType::periodic and f.period > 0) or f.actions->exists(a | (a.execType = ExecutionType::periodic and a.period > 0)))) implies trigger.module.compareTime(trigger.module.period, self, duration) > 0) and trigger.module.functions->forAll(f | (f.execType = ExecutionType::periodic and f.period > 0) implies f.compareTime(f.period, self, duration) > 0) and trigger.module.functions->forAll(f | f.actions->forAll(a | (a.execType = ExecutionType::periodic and a.period > 0) implies a.compareTime(a.period, self, duration) > 0)))" },
        { "Inhibitor", "RSA04_inhibitLayerBelow", "let own : Layer = if module = null then null else module.layer endif, other : Layer = if target = null or target.module = null then null else target.module.layer endif in (own <> null and other <> null) implies other.level = own.level - 1" },
        { "Inhibitor", "RSA16_triggerOfOwnModule", "trigger <> null implies trigger.module = module" },
        { "Suppressor", "RSA04_suppressLayerBelow", "let own : Layer = if module = null then null else module.layer endif, other : Layer = if target = null or target.module = null then null else target.module.layer endif in (own <> null and other <> null) implies other.level = own.level - 1" },
        { "Suppressor", "RSA16_triggerOfOwnModule", "trigger <> null implies trigger.module = module" },
        { "Device", "RSA13_nonNegativeTimes", "period >= 0" },
        { "Device", "RSA20_representableTimes", "representablePeriod(period)" },
        { "Mission", "RSA09_uniqueNames", "goals->isUnique(normalizedName()) and plans->isUnique(normalizedName())" },
        { "Goal", "RSA09_uniqueNames", "subGoals->isUnique(normalizedName())" },
        { "Plan", "RSA09_uniqueNames", "activities->isUnique(normalizedName())" },
        { "Database", "RSA09_uniqueNames", "knowledge->isUnique(normalizedName())" },
        { "Processor", "RSA13_nonNegativeTimes", "linkLatency >= 0" },
        { "Processor", "RSA20_representableTimes", "representable(linkLatency)" },
        { "Processor", "RSA29_packageNameUsable", "packageProblem() = null" },
    };

    /** Class, constraint, OCL text of each invariant left to the interpreter, and why. */
    private static final String[][] INTERPRETED = {
        { "Module", "RSA19_activatedModule", "Set{self}->closure(m | m.ports->select(p | p.oclIsKindOf(EntryPort) and not ((m.execType = ExecutionType::periodic and m.period > 0) or m.functions->exists(f | (f.execType = ExecutionType::periodic and f.period > 0) or f.actions->exists(a | a.execType = ExecutionType::periodic and a.period > 0))))->collect(p | p.oclAsType(EntryPort))->collect(e | e.incoming->select(c | c.source <> null and c.source.module <> null and c.source.dataType = e.dataType and (e.dataType = DataType::structured implies c.source.normalizedMessageType() = e.normalizedMessageType()))->collect(c | c.source.module)->union(e.suppressedBy->select(s | s.trigger <> null and s.trigger.module <> null and s.trigger.dataType = e.dataType and (e.dataType = DataType::structured implies s.trigger.normalizedMessageType() = e.normalizedMessageType()))->collect(s | s.trigger.module))))->including(self)->exists(m | (m.execType = ExecutionType::periodic and m.period > 0) or m.functions->exists(f | (f.execType = ExecutionType::periodic and f.period > 0) or f.actions->exists(a | a.execType = ExecutionType::periodic and a.period > 0)))", "closure() is not translated" },
    };

    /** The index of the compiled invariant, or -1 when it was not compiled or its text has changed since. */
    static int index(String eClass, String constraint, String ocl) {
        for (int i = 0; i < COMPILED.length; i++) {
            if (COMPILED[i][0].equals(eClass) && COMPILED[i][1].equals(constraint)) {
                return COMPILED[i][2].equals(ocl) ? i : -1;
            }
        }
        return -1;
    }

    /** Why the invariant is left to the interpreter, or null when it is not (or its text has changed since). */
    static String interpreted(String eClass, String constraint, String ocl) {
        for (String[] entry : INTERPRETED) {
            if (entry[0].equals(eClass) && entry[1].equals(constraint) && entry[2].equals(ocl)) {
                return entry[3];
            }
        }
        return null;
    }

    /** Evaluates compiled invariant {@code index} on {@code self}: TRUE, FALSE or null; throws {@link Invalid}. */
    static Boolean check(int index, EObject self) {
        switch (index) {
        case 0:
            return inv0((org.rsaml.model.NamedElement) self);
        case 1:
            return inv1((org.rsaml.model.RealTimeElement) self);
        case 2:
            return inv2((org.rsaml.model.RealTimeElement) self);
        case 3:
            return inv3((org.rsaml.model.RealTimeElement) self);
        case 4:
            return inv4((org.rsaml.model.RealTimeElement) self);
        case 5:
            return inv5((org.rsaml.model.RealTimeElement) self);
        case 6:
            return inv6((org.rsaml.model.RealTimeElement) self);
        case 7:
            return inv7((org.rsaml.model.Architecture) self);
        case 8:
            return inv8((org.rsaml.model.Architecture) self);
        case 9:
            return inv9((org.rsaml.model.Architecture) self);
        case 10:
            return inv10((org.rsaml.model.Layer) self);
        case 11:
            return inv11((org.rsaml.model.Layer) self);
        case 12:
            return inv12((org.rsaml.model.Layer) self);
        case 13:
            return inv13((org.rsaml.model.Layer) self);
        case 14:
            return inv14((org.rsaml.model.Module) self);
        case 15:
            return inv15((org.rsaml.model.Module) self);
        case 16:
            return inv16((org.rsaml.model.Module) self);
        case 17:
            return inv17((org.rsaml.model.Module) self);
        case 18:
            return inv18((org.rsaml.model.Function) self);
        case 19:
            return inv19((org.rsaml.model.Function) self);
        case 20:
            return inv20((org.rsaml.model.Function) self);
        case 21:
            return inv21((org.rsaml.model.Action) self);
        case 22:
            return inv22((org.rsaml.model.RTAction) self);
        case 23:
            return inv23((org.rsaml.model.Port) self);
        case 24:
            return inv24((org.rsaml.model.Port) self);
        case 25:
            return inv25((org.rsaml.model.Connection) self);
        case 26:
            return inv26((org.rsaml.model.Connection) self);
        case 27:
            return inv27((org.rsaml.model.SubsumptionLink) self);
        case 28:
            return inv28((org.rsaml.model.SubsumptionLink) self);
        case 29:
            return inv29((org.rsaml.model.SubsumptionLink) self);
        case 30:
            return inv30((org.rsaml.model.Inhibitor) self);
        case 31:
            return inv31((org.rsaml.model.Inhibitor) self);
        case 32:
            return inv32((org.rsaml.model.Suppressor) self);
        case 33:
            return inv33((org.rsaml.model.Suppressor) self);
        case 34:
            return inv34((org.rsaml.model.Device) self);
        case 35:
            return inv35((org.rsaml.model.Device) self);
        case 36:
            return inv36((org.rsaml.model.Mission) self);
        case 37:
            return inv37((org.rsaml.model.Goal) self);
        case 38:
            return inv38((org.rsaml.model.Plan) self);
        case 39:
            return inv39((org.rsaml.model.Database) self);
        case 40:
            return inv40((org.rsaml.model.Processor) self);
        case 41:
            return inv41((org.rsaml.model.Processor) self);
        case 42:
            return inv42((org.rsaml.model.Processor) self);
        default:
            throw new IllegalArgumentException("no compiled invariant " + index);
        }
    }

    /** RSA21_fileNameLength on NamedElement. */
    private static Boolean inv0(org.rsaml.model.NamedElement self) {
        return and(new Operand() { public Boolean get() { return or(new Operand() { public Boolean get() { return eq(self.normalizedName(), null); } }, new Operand() { public Boolean get() { return le(size((String) self.normalizedName()), Long.valueOf(100L)); } }); } }, new Operand() { public Boolean get() { return implies(new Operand() { public Boolean get() { return isKindOf(org.rsaml.model.Port.class, self); } }, new Operand() { public Boolean get() { return or(new Operand() { public Boolean get() { return eq(source(as(org.rsaml.model.Port.class, self)).normalizedMessageType(), null); } }, new Operand() { public Boolean get() { return le(size((String) source(as(org.rsaml.model.Port.class, self)).normalizedMessageType()), Long.valueOf(100L)); } }); } }); } });
    }

    /** RSA10_executionWithinPeriod on RealTimeElement. */
    private static Boolean inv1(org.rsaml.model.RealTimeElement self) {
        return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return eq(self.getExecType(), org.rsaml.model.ExecutionType.PERIODIC); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(self.getPeriod()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return le(Double.valueOf(self.getExecDuration()), Double.valueOf(self.getPeriod())); } });
    }

    /** RSA11_deadlineWithinPeriod on RealTimeElement. */
    private static Boolean inv2(org.rsaml.model.RealTimeElement self) {
        return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return eq(self.getExecType(), org.rsaml.model.ExecutionType.PERIODIC); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(self.getPeriod()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(self.getDelay()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return le(Double.valueOf(self.getDelay()), Double.valueOf(self.getPeriod())); } });
    }

    /** RSA12_periodicHasPeriod on RealTimeElement. */
    private static Boolean inv3(org.rsaml.model.RealTimeElement self) {
        return implies(new Operand() { public Boolean get() { return eq(self.getExecType(), org.rsaml.model.ExecutionType.PERIODIC); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(self.getPeriod()), Long.valueOf(0L)); } });
    }

    /** RSA13_nonNegativeTimes on RealTimeElement. */
    private static Boolean inv4(org.rsaml.model.RealTimeElement self) {
        return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ge(Double.valueOf(self.getPeriod()), Long.valueOf(0L)); } }, new Operand() { public Boolean get() { return ge(Double.valueOf(self.getDelay()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return ge(Double.valueOf(self.getExecDuration()), Long.valueOf(0L)); } });
    }

    /** RSA17_executionWithinDeadline on RealTimeElement. */
    private static Boolean inv5(org.rsaml.model.RealTimeElement self) {
        return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return eq(self.getType(), org.rsaml.model.ElementType.REAL_TIME); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(self.getDelay()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return le(Double.valueOf(self.getExecDuration()), Double.valueOf(self.getDelay())); } });
    }

    /** RSA20_representableTimes on RealTimeElement. */
    private static Boolean inv6(org.rsaml.model.RealTimeElement self) {
        return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return Boolean.valueOf(self.representablePeriod(((Number) source(Double.valueOf(self.getPeriod()))).doubleValue())); } }, new Operand() { public Boolean get() { return Boolean.valueOf(self.representable(((Number) source(Double.valueOf(self.getDelay()))).doubleValue())); } }); } }, new Operand() { public Boolean get() { return Boolean.valueOf(self.representable(((Number) source(Double.valueOf(self.getExecDuration()))).doubleValue())); } });
    }

    /** RSA01_declaredLayerCount on Architecture. */
    private static Boolean inv7(org.rsaml.model.Architecture self) {
        return eq(Long.valueOf(self.getDeclaredLayers()), size(self.getLayers()));
    }

    /** RSA09_uniqueNames on Architecture. */
    private static Boolean inv8(org.rsaml.model.Architecture self) {
        return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return isUnique(self.getLayers(), new Body<org.rsaml.model.Layer, Object>() { public Object apply(org.rsaml.model.Layer v_temp1) { return v_temp1.normalizedName(); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getSensors(), new Body<org.rsaml.model.Sensor, Object>() { public Object apply(org.rsaml.model.Sensor v_temp2) { return v_temp2.normalizedName(); } }); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getActuators(), new Body<org.rsaml.model.Actuator, Object>() { public Object apply(org.rsaml.model.Actuator v_temp3) { return v_temp3.normalizedName(); } }); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getMissions(), new Body<org.rsaml.model.Mission, Object>() { public Object apply(org.rsaml.model.Mission v_temp4) { return v_temp4.normalizedName(); } }); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getSupervisors(), new Body<org.rsaml.model.Supervisor, Object>() { public Object apply(org.rsaml.model.Supervisor v_temp5) { return v_temp5.normalizedName(); } }); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getOrders(), new Body<org.rsaml.model.Order, Object>() { public Object apply(org.rsaml.model.Order v_temp6) { return v_temp6.normalizedName(); } }); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getDatabases(), new Body<org.rsaml.model.Database, Object>() { public Object apply(org.rsaml.model.Database v_temp7) { return v_temp7.normalizedName(); } }); } });
    }

    /** RSA14_layerLevels on Architecture. */
    private static Boolean inv9(org.rsaml.model.Architecture self) {
        return and(new Operand() { public Boolean get() { return isUnique(self.getLayers(), new Body<org.rsaml.model.Layer, Object>() { public Object apply(org.rsaml.model.Layer v_temp1) { return Long.valueOf(v_temp1.getLevel()); } }); } }, new Operand() { public Boolean get() { return forAll(self.getLayers(), new Body<org.rsaml.model.Layer, Boolean>() { public Boolean apply(org.rsaml.model.Layer v_l) { return and(new Operand() { public Boolean get() { return ge(Long.valueOf(v_l.getLevel()), Long.valueOf(0L)); } }, new Operand() { public Boolean get() { return lt(Long.valueOf(v_l.getLevel()), size(self.getLayers())); } }); } }); } });
    }

    /** RSA09_uniqueNames on Layer. */
    private static Boolean inv10(org.rsaml.model.Layer self) {
        return isUnique(self.getModules(), new Body<org.rsaml.model.Module, Object>() { public Object apply(org.rsaml.model.Module v_temp1) { return v_temp1.normalizedName(); } });
    }

    /** RSA13_nonNegativeTimes on Layer. */
    private static Boolean inv11(org.rsaml.model.Layer self) {
        return ge(Double.valueOf(self.getMaxExecTime()), Long.valueOf(0L));
    }

    /** RSA20_representableTimes on Layer. */
    private static Boolean inv12(org.rsaml.model.Layer self) {
        return Boolean.valueOf(self.representable(((Number) source(Double.valueOf(self.getMaxExecTime()))).doubleValue()));
    }

    /** RSA29_packageNameUsable on Layer. */
    private static Boolean inv13(org.rsaml.model.Layer self) {
        return eq(self.packageProblem(), null);
    }

    /** RSA05_realTimeModuleTiming on Module. */
    private static Boolean inv14(org.rsaml.model.Module self) {
        return implies(new Operand() { public Boolean get() { return eq(self.getType(), org.rsaml.model.ElementType.REAL_TIME); } }, new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return gt(Double.valueOf(self.getPeriod()), Long.valueOf(0L)); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(self.getDelay()), Long.valueOf(0L)); } }); } });
    }

    /** RSA06_realTimeModuleFunctions on Module. */
    private static Boolean inv15(org.rsaml.model.Module self) {
        return implies(new Operand() { public Boolean get() { return eq(self.getType(), org.rsaml.model.ElementType.REAL_TIME); } }, new Operand() { public Boolean get() { return forAll(self.getFunctions(), new Body<org.rsaml.model.Function, Boolean>() { public Boolean apply(org.rsaml.model.Function v_f) { return eq(v_f.getType(), org.rsaml.model.ElementType.REAL_TIME); } }); } });
    }

    /** RSA08_layerExecutionBudget on Module. */
    private static Boolean inv16(org.rsaml.model.Module self) {
        return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(self.getLayer(), null); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(source(self.getLayer()).getMaxExecTime()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return le(Long.valueOf(self.compareTime(((Number) source(Double.valueOf(self.getExecDuration()))).doubleValue(), (org.rsaml.model.TimeScaled) self.getLayer(), ((Number) source(Double.valueOf(source(self.getLayer()).getMaxExecTime()))).doubleValue())), Long.valueOf(0L)); } });
    }

    /** RSA09_uniqueNames on Module. */
    private static Boolean inv17(org.rsaml.model.Module self) {
        return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return isUnique(self.getPorts(), new Body<org.rsaml.model.Port, Object>() { public Object apply(org.rsaml.model.Port v_temp1) { return v_temp1.normalizedName(); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getFunctions(), new Body<org.rsaml.model.Function, Object>() { public Object apply(org.rsaml.model.Function v_temp2) { return v_temp2.normalizedName(); } }); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getInhibitors(), new Body<org.rsaml.model.Inhibitor, Object>() { public Object apply(org.rsaml.model.Inhibitor v_temp3) { return v_temp3.normalizedName(); } }); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getSuppressors(), new Body<org.rsaml.model.Suppressor, Object>() { public Object apply(org.rsaml.model.Suppressor v_temp4) { return v_temp4.normalizedName(); } }); } });
    }

    /** RSA07_realTimeFunctionActions on Function. */
    private static Boolean inv18(org.rsaml.model.Function self) {
        return implies(new Operand() { public Boolean get() { return eq(self.getType(), org.rsaml.model.ElementType.REAL_TIME); } }, new Operand() { public Boolean get() { return forAll(self.getActions(), new Body<org.rsaml.model.Action, Boolean>() { public Boolean apply(org.rsaml.model.Action v_a) { return eq(v_a.getType(), org.rsaml.model.ElementType.REAL_TIME); } }); } });
    }

    /** RSA09_uniqueNames on Function. */
    private static Boolean inv19(org.rsaml.model.Function self) {
        return isUnique(self.getActions(), new Body<org.rsaml.model.Action, Object>() { public Object apply(org.rsaml.model.Action v_temp1) { return v_temp1.normalizedName(); } });
    }

    /** RSA27_functionWithinBudget on Function. */
    private static Boolean inv20(org.rsaml.model.Function self) {
        return and(new Operand() { public Boolean get() { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(self.getModule(), null); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(source(self.getModule()).getExecDuration()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return le(Long.valueOf(self.compareTime(((Number) source(Double.valueOf(self.getExecDuration()))).doubleValue(), (org.rsaml.model.TimeScaled) self.getModule(), ((Number) source(Double.valueOf(source(self.getModule()).getExecDuration()))).doubleValue())), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(self.getModule(), null); } }, new Operand() { public Boolean get() { return ne(source(self.getModule()).getLayer(), null); } }); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(source(source(self.getModule()).getLayer()).getMaxExecTime()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return le(Long.valueOf(self.compareTime(((Number) source(Double.valueOf(self.getExecDuration()))).doubleValue(), (org.rsaml.model.TimeScaled) source(self.getModule()).getLayer(), ((Number) source(Double.valueOf(source(source(self.getModule()).getLayer()).getMaxExecTime()))).doubleValue())), Long.valueOf(0L)); } }); } });
    }

    /** RSA27_actionWithinBudget on Action. */
    private static Boolean inv21(org.rsaml.model.Action self) {
        return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(self.getFunction(), null); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(source(self.getFunction()).getExecDuration()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return le(Long.valueOf(self.compareTime(((Number) source(Double.valueOf(self.getExecDuration()))).doubleValue(), (org.rsaml.model.TimeScaled) self.getFunction(), ((Number) source(Double.valueOf(source(self.getFunction()).getExecDuration()))).doubleValue())), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(self.getFunction(), null); } }, new Operand() { public Boolean get() { return ne(source(self.getFunction()).getModule(), null); } }); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(source(source(self.getFunction()).getModule()).getExecDuration()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return le(Long.valueOf(self.compareTime(((Number) source(Double.valueOf(self.getExecDuration()))).doubleValue(), (org.rsaml.model.TimeScaled) source(self.getFunction()).getModule(), ((Number) source(Double.valueOf(source(source(self.getFunction()).getModule()).getExecDuration()))).doubleValue())), Long.valueOf(0L)); } }); } }); } }, new Operand() { public Boolean get() { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(self.getFunction(), null); } }, new Operand() { public Boolean get() { return ne(source(self.getFunction()).getModule(), null); } }); } }, new Operand() { public Boolean get() { return ne(source(source(self.getFunction()).getModule()).getLayer(), null); } }); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(source(source(source(self.getFunction()).getModule()).getLayer()).getMaxExecTime()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return le(Long.valueOf(self.compareTime(((Number) source(Double.valueOf(self.getExecDuration()))).doubleValue(), (org.rsaml.model.TimeScaled) source(source(self.getFunction()).getModule()).getLayer(), ((Number) source(Double.valueOf(source(source(source(self.getFunction()).getModule()).getLayer()).getMaxExecTime()))).doubleValue())), Long.valueOf(0L)); } }); } });
    }

    /** RSA15_rtActionIsRealTime on RTAction. */
    private static Boolean inv22(org.rsaml.model.RTAction self) {
        return eq(self.getType(), org.rsaml.model.ElementType.REAL_TIME);
    }

    /** RSA18_structuredPortNamesMessageType on Port. */
    private static Boolean inv23(org.rsaml.model.Port self) {
        return implies(new Operand() { public Boolean get() { return eq(self.getDataType(), org.rsaml.model.DataType.STRUCTURED); } }, new Operand() { public Boolean get() { return ne(self.normalizedMessageType(), null); } });
    }

    /** RSA28_topicNameUsable on Port. */
    private static Boolean inv24(org.rsaml.model.Port self) {
        return eq(self.topicProblem(), null);
    }

    /** RSA02_connectedPortTypes on Connection. */
    private static Boolean inv25(org.rsaml.model.Connection self) {
        return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(self.getSource(), null); } }, new Operand() { public Boolean get() { return ne(self.getTarget(), null); } }); } }, new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return eq(source(self.getSource()).getDataType(), source(self.getTarget()).getDataType()); } }, new Operand() { public Boolean get() { return implies(new Operand() { public Boolean get() { return eq(source(self.getSource()).getDataType(), org.rsaml.model.DataType.STRUCTURED); } }, new Operand() { public Boolean get() { return eq(source(self.getSource()).normalizedMessageType(), source(self.getTarget()).normalizedMessageType()); } }); } }); } });
    }

    /** RSA03_adjacentLayerCommunication on Connection. */
    private static Boolean inv26(org.rsaml.model.Connection self) {
        return let((test(or(new Operand() { public Boolean get() { return eq(self.getSource(), null); } }, new Operand() { public Boolean get() { return eq(source(self.getSource()).getModule(), null); } })) ? (org.rsaml.model.Layer) null : (org.rsaml.model.Layer) source(source(self.getSource()).getModule()).getLayer()), new Body<org.rsaml.model.Layer, Boolean>() { public Boolean apply(org.rsaml.model.Layer v_from) { return let((test(or(new Operand() { public Boolean get() { return eq(self.getTarget(), null); } }, new Operand() { public Boolean get() { return eq(source(self.getTarget()).getModule(), null); } })) ? (org.rsaml.model.Layer) null : (org.rsaml.model.Layer) source(source(self.getTarget()).getModule()).getLayer()), new Body<org.rsaml.model.Layer, Boolean>() { public Boolean apply(org.rsaml.model.Layer v_to) { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(v_from, null); } }, new Operand() { public Boolean get() { return ne(v_to, null); } }); } }, new Operand() { public Boolean get() { return le(abs(minus(Long.valueOf(source(v_from).getLevel()), Long.valueOf(source(v_to).getLevel()))), Long.valueOf(1L)); } }); } }); } });
    }

    /** RSA13_nonNegativeTimes on SubsumptionLink. */
    private static Boolean inv27(org.rsaml.model.SubsumptionLink self) {
        return ge(Double.valueOf(self.getDuration()), Long.valueOf(0L));
    }

    /** RSA20_representableTimes on SubsumptionLink. */
    private static Boolean inv28(org.rsaml.model.SubsumptionLink self) {
        return Boolean.valueOf(self.representable(((Number) source(Double.valueOf(self.getDuration()))).doubleValue()));
    }

    /** RSA26_durationBelowTriggerPeriod on SubsumptionLink. */
    private static Boolean inv29(org.rsaml.model.SubsumptionLink self) {
        return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(self.getTrigger(), null); } }, new Operand() { public Boolean get() { return ne(source(self.getTrigger()).getModule(), null); } }); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(self.getDuration()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return eq(source(source(self.getTrigger()).getModule()).getExecType(), org.rsaml.model.ExecutionType.PERIODIC); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(source(source(self.getTrigger()).getModule()).getPeriod()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return or(new Operand() { public Boolean get() { return exists(source(source(self.getTrigger()).getModule()).getFunctions(), new Body<org.rsaml.model.Function, Boolean>() { public Boolean apply(org.rsaml.model.Function v_f) { return not(and(new Operand() { public Boolean get() { return eq(v_f.getExecType(), org.rsaml.model.ExecutionType.PERIODIC); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(v_f.getPeriod()), Long.valueOf(0L)); } })); } }); } }, new Operand() { public Boolean get() { return not(exists(source(source(self.getTrigger()).getModule()).getFunctions(), new Body<org.rsaml.model.Function, Boolean>() { public Boolean apply(org.rsaml.model.Function v_f) { return or(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return eq(v_f.getExecType(), org.rsaml.model.ExecutionType.PERIODIC); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(v_f.getPeriod()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return exists(v_f.getActions(), new Body<org.rsaml.model.Action, Boolean>() { public Boolean apply(org.rsaml.model.Action v_a) { return and(new Operand() { public Boolean get() { return eq(v_a.getExecType(), org.rsaml.model.ExecutionType.PERIODIC); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(v_a.getPeriod()), Long.valueOf(0L)); } }); } }); } }); } })); } }); } }); } }, new Operand() { public Boolean get() { return gt(Long.valueOf(source(source(self.getTrigger()).getModule()).compareTime(((Number) source(Double.valueOf(source(source(self.getTrigger()).getModule()).getPeriod()))).doubleValue(), (org.rsaml.model.TimeScaled) self, ((Number) source(Double.valueOf(self.getDuration()))).doubleValue())), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return forAll(source(source(self.getTrigger()).getModule()).getFunctions(), new Body<org.rsaml.model.Function, Boolean>() { public Boolean apply(org.rsaml.model.Function v_f) { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return eq(v_f.getExecType(), org.rsaml.model.ExecutionType.PERIODIC); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(v_f.getPeriod()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return gt(Long.valueOf(v_f.compareTime(((Number) source(Double.valueOf(v_f.getPeriod()))).doubleValue(), (org.rsaml.model.TimeScaled) self, ((Number) source(Double.valueOf(self.getDuration()))).doubleValue())), Long.valueOf(0L)); } }); } }); } }); } }, new Operand() { public Boolean get() { return forAll(source(source(self.getTrigger()).getModule()).getFunctions(), new Body<org.rsaml.model.Function, Boolean>() { public Boolean apply(org.rsaml.model.Function v_f) { return forAll(v_f.getActions(), new Body<org.rsaml.model.Action, Boolean>() { public Boolean apply(org.rsaml.model.Action v_a) { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return eq(v_a.getExecType(), org.rsaml.model.ExecutionType.PERIODIC); } }, new Operand() { public Boolean get() { return gt(Double.valueOf(v_a.getPeriod()), Long.valueOf(0L)); } }); } }, new Operand() { public Boolean get() { return gt(Long.valueOf(v_a.compareTime(((Number) source(Double.valueOf(v_a.getPeriod()))).doubleValue(), (org.rsaml.model.TimeScaled) self, ((Number) source(Double.valueOf(self.getDuration()))).doubleValue())), Long.valueOf(0L)); } }); } }); } }); } }); } });
    }

    /** RSA04_inhibitLayerBelow on Inhibitor. */
    private static Boolean inv30(org.rsaml.model.Inhibitor self) {
        return let((test(eq(self.getModule(), null)) ? (org.rsaml.model.Layer) null : (org.rsaml.model.Layer) source(self.getModule()).getLayer()), new Body<org.rsaml.model.Layer, Boolean>() { public Boolean apply(org.rsaml.model.Layer v_own) { return let((test(or(new Operand() { public Boolean get() { return eq(self.getTarget(), null); } }, new Operand() { public Boolean get() { return eq(source(self.getTarget()).getModule(), null); } })) ? (org.rsaml.model.Layer) null : (org.rsaml.model.Layer) source(source(self.getTarget()).getModule()).getLayer()), new Body<org.rsaml.model.Layer, Boolean>() { public Boolean apply(org.rsaml.model.Layer v_other) { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(v_own, null); } }, new Operand() { public Boolean get() { return ne(v_other, null); } }); } }, new Operand() { public Boolean get() { return eq(Long.valueOf(source(v_other).getLevel()), minus(Long.valueOf(source(v_own).getLevel()), Long.valueOf(1L))); } }); } }); } });
    }

    /** RSA16_triggerOfOwnModule on Inhibitor. */
    private static Boolean inv31(org.rsaml.model.Inhibitor self) {
        return implies(new Operand() { public Boolean get() { return ne(self.getTrigger(), null); } }, new Operand() { public Boolean get() { return eq(source(self.getTrigger()).getModule(), self.getModule()); } });
    }

    /** RSA04_suppressLayerBelow on Suppressor. */
    private static Boolean inv32(org.rsaml.model.Suppressor self) {
        return let((test(eq(self.getModule(), null)) ? (org.rsaml.model.Layer) null : (org.rsaml.model.Layer) source(self.getModule()).getLayer()), new Body<org.rsaml.model.Layer, Boolean>() { public Boolean apply(org.rsaml.model.Layer v_own) { return let((test(or(new Operand() { public Boolean get() { return eq(self.getTarget(), null); } }, new Operand() { public Boolean get() { return eq(source(self.getTarget()).getModule(), null); } })) ? (org.rsaml.model.Layer) null : (org.rsaml.model.Layer) source(source(self.getTarget()).getModule()).getLayer()), new Body<org.rsaml.model.Layer, Boolean>() { public Boolean apply(org.rsaml.model.Layer v_other) { return implies(new Operand() { public Boolean get() { return and(new Operand() { public Boolean get() { return ne(v_own, null); } }, new Operand() { public Boolean get() { return ne(v_other, null); } }); } }, new Operand() { public Boolean get() { return eq(Long.valueOf(source(v_other).getLevel()), minus(Long.valueOf(source(v_own).getLevel()), Long.valueOf(1L))); } }); } }); } });
    }

    /** RSA16_triggerOfOwnModule on Suppressor. */
    private static Boolean inv33(org.rsaml.model.Suppressor self) {
        return implies(new Operand() { public Boolean get() { return ne(self.getTrigger(), null); } }, new Operand() { public Boolean get() { return eq(source(self.getTrigger()).getModule(), self.getModule()); } });
    }

    /** RSA13_nonNegativeTimes on Device. */
    private static Boolean inv34(org.rsaml.model.Device self) {
        return ge(Double.valueOf(self.getPeriod()), Long.valueOf(0L));
    }

    /** RSA20_representableTimes on Device. */
    private static Boolean inv35(org.rsaml.model.Device self) {
        return Boolean.valueOf(self.representablePeriod(((Number) source(Double.valueOf(self.getPeriod()))).doubleValue()));
    }

    /** RSA09_uniqueNames on Mission. */
    private static Boolean inv36(org.rsaml.model.Mission self) {
        return and(new Operand() { public Boolean get() { return isUnique(self.getGoals(), new Body<org.rsaml.model.Goal, Object>() { public Object apply(org.rsaml.model.Goal v_temp1) { return v_temp1.normalizedName(); } }); } }, new Operand() { public Boolean get() { return isUnique(self.getPlans(), new Body<org.rsaml.model.Plan, Object>() { public Object apply(org.rsaml.model.Plan v_temp2) { return v_temp2.normalizedName(); } }); } });
    }

    /** RSA09_uniqueNames on Goal. */
    private static Boolean inv37(org.rsaml.model.Goal self) {
        return isUnique(self.getSubGoals(), new Body<org.rsaml.model.Goal, Object>() { public Object apply(org.rsaml.model.Goal v_temp1) { return v_temp1.normalizedName(); } });
    }

    /** RSA09_uniqueNames on Plan. */
    private static Boolean inv38(org.rsaml.model.Plan self) {
        return isUnique(self.getActivities(), new Body<org.rsaml.model.Activity, Object>() { public Object apply(org.rsaml.model.Activity v_temp1) { return v_temp1.normalizedName(); } });
    }

    /** RSA09_uniqueNames on Database. */
    private static Boolean inv39(org.rsaml.model.Database self) {
        return isUnique(self.getKnowledge(), new Body<org.rsaml.model.Knowledge, Object>() { public Object apply(org.rsaml.model.Knowledge v_temp1) { return v_temp1.normalizedName(); } });
    }

    /** RSA13_nonNegativeTimes on Processor. */
    private static Boolean inv40(org.rsaml.model.Processor self) {
        return ge(Double.valueOf(self.getLinkLatency()), Long.valueOf(0L));
    }

    /** RSA20_representableTimes on Processor. */
    private static Boolean inv41(org.rsaml.model.Processor self) {
        return Boolean.valueOf(self.representable(((Number) source(Double.valueOf(self.getLinkLatency()))).doubleValue()));
    }

    /** RSA29_packageNameUsable on Processor. */
    private static Boolean inv42(org.rsaml.model.Processor self) {
        return eq(self.packageProblem(), null);
    }
}
