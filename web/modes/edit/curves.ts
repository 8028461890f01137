import { CatmullRom, type Parameterization } from '../../../src/index.js';

/** One curve as plain data: what undo snapshots, autosave and export keep. */
export interface CurveSnapshot {
  closed: boolean;
  /** Control points, flat x,y. */
  points: number[];
  parameterization: Parameterization;
  /** Tangent overrides: [control point, x, y]. */
  tangents: [number, number, number][];
  /** Pen pressure per control point, when the curve was drawn with a pen. */
  pressure?: number[];
}

function snapshotOf(c: CatmullRom, pressure: number[] | undefined): CurveSnapshot {
  const tangents: [number, number, number][] = [];
  for (let i = 0; i < c.count; i++) {
    if (c.tangentOverridden(i)) {
      const [x, y] = c.tangent(i);
      tangents.push([i, x, y]);
    }
  }
  return {
    closed: c.closed,
    points: Array.from(c.points()),
    parameterization: c.parameterization,
    tangents,
    ...(pressure && pressure.length === c.count ? { pressure } : {}),
  };
}

/** Reads a snapshot back (throws on damaged data: callers of stored data catch). */
export function curveFromSnapshot(s: CurveSnapshot): CatmullRom {
  const c = CatmullRom.create(s.points, { closed: s.closed, parameterization: s.parameterization });
  try {
    for (const [i, x, y] of s.tangents ?? []) c.setTangent(i, [x, y]);
  } catch (err) {
    c.dispose();
    throw err;
  }
  return c;
}

/**
 * The Catmull-Rom curves of one document in Edit mode: wasm curves plus what they carry beside
 * (pen pressure). Undo works on snapshots of the whole list (a few curves of a few hundred points).
 */
export class EditCurves {
  private items: { curve: CatmullRom; pressure?: number[] }[] = [];

  get curves(): readonly CatmullRom[] {
    return this.items.map((i) => i.curve);
  }

  get count(): number {
    return this.items.length;
  }

  curve(i: number): CatmullRom | undefined {
    return this.items[i]?.curve;
  }

  pressure(i: number): number[] | undefined {
    const item = this.items[i];
    return item?.pressure && item.pressure.length === item.curve.count ? item.pressure : undefined;
  }

  snapshot(): CurveSnapshot[] {
    return this.items.map((i) => snapshotOf(i.curve, i.pressure));
  }

  /** Replaces every curve by the snapshot's. */
  restore(snapshot: readonly CurveSnapshot[]): void {
    const made = snapshot.map((s) => ({ curve: curveFromSnapshot(s), pressure: s.pressure }));
    this.dispose();
    this.items = made;
  }

  add(curve: CatmullRom, pressure?: number[]): number {
    this.items.push({ curve, pressure });
    return this.items.length - 1;
  }

  dispose(): void {
    for (const i of this.items) i.curve.dispose();
    this.items = [];
  }
}
