import { Color, SRGBColorSpace } from 'three';

/** Skin mode's colors (sRGB), shared by the canvas layers and the panel's legends. */
export const SKIN_COLORS = {
  /** The target when the heat map is off. */
  target: '#2b3440',
  naive: '#15aabf',
  handle: '#ffffff',
  selected: '#ffe066',
  gizmo: '#5aa9ff',
};

/** The paper's heat map: purple at the minimum through blue, green, yellow to red at the maximum. */
export const HEAT_STOPS = ['#7b2ff7', '#1c7ed6', '#12b886', '#fab005', '#f03e3e'];
/** A handle's weight field: 0 dark … violet … red … 1 yellow (inferno-like, apart from drawings' own colors). */
export const WEIGHT_STOPS = ['#343a40', '#7048e8', '#f03e3e', '#ffd43b'];

function parse(hex: string): [number, number, number] {
  const n = parseInt(hex.slice(1), 16);
  return [((n >> 16) & 255) / 255, ((n >> 8) & 255) / 255, (n & 255) / 255];
}

/** A color ramp through `stops` (evenly spaced), in sRGB; `at(t)` clamps t to [0, 1]. */
export class Ramp {
  private readonly rgb: [number, number, number][];
  private readonly color = new Color();

  constructor(stops: readonly string[]) {
    this.rgb = stops.map(parse);
  }

  /** The color at t as linear RGB (for three.js vertex colors), written to `out` at `offset`. */
  linearAt(t: number, out: Float32Array, offset: number): void {
    const [r, g, b] = this.srgbAt(t);
    this.color.setRGB(r, g, b, SRGBColorSpace);
    out[offset] = this.color.r;
    out[offset + 1] = this.color.g;
    out[offset + 2] = this.color.b;
  }

  /** The color at t as sRGB, written to `out` at `offset`. */
  srgbInto(t: number, out: Float32Array, offset: number): void {
    const [r, g, b] = this.srgbAt(t);
    out[offset] = r;
    out[offset + 1] = g;
    out[offset + 2] = b;
  }

  srgbAt(t: number): [number, number, number] {
    const n = this.rgb.length - 1;
    const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * n;
    const i = Math.min(n - 1, Math.floor(x)), f = x - i;
    const a = this.rgb[i], b = this.rgb[i + 1];
    return [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])];
  }

  /** A CSS linear-gradient of the ramp (for legends). */
  css(direction = 'to right'): string {
    return `linear-gradient(${direction}, ${this.rgb.map((c) => `rgb(${c.map((v) => Math.round(v * 255)).join(' ')})`).join(', ')})`;
  }
}

export const HEAT = new Ramp(HEAT_STOPS);
export const WEIGHT = new Ramp(WEIGHT_STOPS);
