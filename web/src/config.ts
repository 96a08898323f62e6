// The text forms of budgets and perceptual models the server's flags use ("0.3x", "f2:5:deg"),
// parsed into and formatted from the protocol's messages, so the page's controls read like the CLI.
import { create } from "@bufbuild/protobuf";
import {
  BudgetSchema,
  EccentricityUnit,
  ExactBudgetSchema,
  ModelF1Schema,
  ModelF2RangeSchema,
  ModelF2Schema,
  ModelF3Schema,
  PerceptualModelSchema,
  Scheduler,
  Truth,
  type Budget,
  type PerceptualModel,
} from "./gen/foveal/v1/foveal_pb";

/** Scheduler names as the CLI spells them, in protocol enum order. */
export const SCHEDULERS: [string, Scheduler][] = [
  ["priced", Scheduler.PRICED],
  ["round-robin", Scheduler.ROUND_ROBIN],
  ["sequential", Scheduler.SEQUENTIAL],
  ["sorted-sequential", Scheduler.SORTED_SEQUENTIAL],
  ["priority-only", Scheduler.PRIORITY_ONLY],
  ["priority-sorted", Scheduler.PRIORITY_SORTED],
  ["expected-gain", Scheduler.EXPECTED_GAIN],
];

export function schedulerName(s: Scheduler | undefined): string {
  return SCHEDULERS.find(([, v]) => v === s)?.[0] ?? "unknown";
}

/** Truth names as the CLI spells them (`--truth`), with what each means, in protocol enum order. */
export const TRUTHS: [string, Truth, string][] = [
  ["shape", Truth.SHAPE, "colliding: the drawn stars touch"],
  ["leaf-spheres", Truth.LEAF_SPHERES, "colliding: leaf spheres overlap (the paper's definition)"],
];

export function truthName(t: Truth | undefined): string {
  return TRUTHS.find(([, v]) => v === t)?.[0] ?? "unknown";
}

/** What a truth means, for the page. */
export function truthMeaning(t: Truth | undefined): string {
  return TRUTHS.find(([, v]) => v === t)?.[2] ?? "the server did not say what colliding means";
}

/** `exact`, `zero`, `4ms`, `20000tests` or `0.3x`; throws with what is accepted otherwise. */
export function parseBudget(text: string): Budget {
  const t = text.trim().toLowerCase();
  const num = (s: string) => {
    const v = Number(s);
    if (s === "" || !Number.isFinite(v)) throw new Error(`budget "${text}": "${s}" is not a number`);
    return v;
  };
  if (t === "exact") return create(BudgetSchema, { kind: { case: "exact", value: create(ExactBudgetSchema) } });
  if (t === "zero") return create(BudgetSchema, { kind: { case: "interruptAtZero", value: true } });
  if (t.endsWith("ms")) return create(BudgetSchema, { kind: { case: "wallMs", value: num(t.slice(0, -2)) } });
  if (t.endsWith("tests")) {
    const v = num(t.slice(0, -5));
    if (!Number.isInteger(v) || v < 0) throw new Error(`budget "${text}": sphere tests must be a whole number`);
    return create(BudgetSchema, { kind: { case: "sphereTests", value: BigInt(v) } });
  }
  if (t.endsWith("x")) return create(BudgetSchema, { kind: { case: "fractionOfExact", value: num(t.slice(0, -1)) } });
  throw new Error(`budget "${text}": use exact, zero, 4ms, 20000tests or 0.3x`);
}

export function formatBudget(b: Budget | undefined): string {
  switch (b?.kind.case) {
    case "exact":
      return "exact";
    case "interruptAtZero":
      return "zero";
    case "wallMs":
      return `${b.kind.value}ms`;
    case "sphereTests":
      return `${b.kind.value}tests`;
    case "fractionOfExact":
      return `${b.kind.value}x`;
    default:
      return "";
  }
}

const UNITS: Record<string, EccentricityUnit> = { deg: EccentricityUnit.DEGREES, px: EccentricityUnit.PIXELS };

/** `f1[:unit]`, `f2:<C>[:unit]`, `f2range:<Cmin>,<Cmax>[:unit]`, `f3:<c1>,<c2>,<c3>,<e1>,<e2>[:unit]`. */
export function parseModel(text: string): PerceptualModel {
  const parts = text.trim().toLowerCase().split(":");
  let unit = EccentricityUnit.DEGREES;
  const last = parts[parts.length - 1];
  if (parts.length > 1 && last in UNITS) {
    unit = UNITS[last];
    parts.pop();
  }
  const nums = (s: string | undefined, n: number) => {
    const v = (s ?? "").split(",").map(Number);
    if (v.length !== n || v.some((x) => !Number.isFinite(x))) {
      throw new Error(`model "${text}": expected ${n} number${n > 1 ? "s" : ""} after "${parts[0]}:"`);
    }
    return v;
  };
  const m = (model: PerceptualModel["model"]) => create(PerceptualModelSchema, { model, eccentricityUnit: unit });
  switch (parts[0]) {
    case "f1":
      return m({ case: "f1", value: create(ModelF1Schema) });
    case "f2": {
      const [c] = nums(parts[1], 1);
      return m({ case: "f2", value: create(ModelF2Schema, { c }) });
    }
    case "f2range": {
      const [cMin, cMax] = nums(parts[1], 2);
      return m({ case: "f2Range", value: create(ModelF2RangeSchema, { cMin, cMax }) });
    }
    case "f3": {
      const [c1, c2, c3, e1, e2] = nums(parts[1], 5);
      return m({ case: "f3", value: create(ModelF3Schema, { c1, c2, c3, e1, e2 }) });
    }
    default:
      throw new Error(`model "${text}": use f1, f2:<C>, f2range:<Cmin>,<Cmax> or f3:<c1>,<c2>,<c3>,<e1>,<e2>, optionally :deg or :px`);
  }
}

export function formatModel(p: PerceptualModel | undefined): string {
  if (!p) return "";
  const unit = p.eccentricityUnit === EccentricityUnit.PIXELS ? "px" : "deg";
  switch (p.model.case) {
    case "f1":
      return `f1:${unit}`;
    case "f2":
      return `f2:${p.model.value.c}:${unit}`;
    case "f2Range":
      return `f2range:${p.model.value.cMin},${p.model.value.cMax}:${unit}`;
    case "f3": {
      const v = p.model.value;
      return `f3:${v.c1},${v.c2},${v.c3},${v.e1},${v.e2}:${unit}`;
    }
    default:
      return "";
  }
}
