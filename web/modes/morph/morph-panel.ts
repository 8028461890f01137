import type { MorphInterpolation } from '../../../src/index.js';
import { h, noFocusOnClick } from '../../ui/dom.js';
import { facts, section } from '../../ui/panel.js';
import { MORPH_SAMPLES } from './samples.js';
import type { KeyChoice } from './spec.js';

export interface MorphPanelActions {
  chooseKey(which: 'a' | 'b', source: string): void;
  openKey(which: 'a' | 'b', file: File): void;
  openFont(which: 'a' | 'b', file: File, char: string): void;
  setInterpolation(m: MorphInterpolation): void;
  seek(t: number, live: boolean): void;
  togglePlay(): void;
  setLayer(name: 'onion' | 'lines', on: boolean): void;
  clearPins(): void;
  exportAnimated(format: 'smil' | 'css'): void;
  exportFrames(): void;
}

/** The morph mode's side panel: keys, interpolation, t and play, layers, pins, numbers, export. */
export class MorphPanel {
  readonly sections: HTMLElement[];
  private readonly selects: Record<'a' | 'b', HTMLSelectElement>;
  private readonly interp = new Map<MorphInterpolation, HTMLButtonElement>();
  readonly slider: HTMLInputElement;
  private readonly tLabel = h('span', { 'data-testid': 'morph-t' });
  private readonly play: HTMLButtonElement;
  private readonly info = facts(['Contours', 'Work', 'Correspondence', 'Frame', 'Pins']);
  private readonly error = h('p', { class: 'rig-error', 'data-testid': 'morph-error', hidden: true });
  private readonly boxes = new Map<'onion' | 'lines', HTMLInputElement>();

  constructor(actions: MorphPanelActions) {
    const keySelect = (which: 'a' | 'b') => {
      const s = h('select', { 'data-testid': `morph-key-${which}`, 'aria-label': which === 'a' ? 'First key' : 'Second key' });
      if (which === 'a') s.append(h('option', { value: 'current' }, 'The open drawing'));
      for (const sample of MORPH_SAMPLES) s.append(h('option', { value: sample.id }, sample.title));
      s.append(h('option', { value: 'file', disabled: true }, 'A file…'));
      s.addEventListener('change', () => actions.chooseKey(which, s.value));
      return s;
    };
    this.selects = { a: keySelect('a'), b: keySelect('b') };
    const openButton = (which: 'a' | 'b') => {
      const input = h('input', { type: 'file', accept: '.svg,image/svg+xml', hidden: true, 'data-testid': `morph-open-${which}` });
      input.addEventListener('change', () => {
        const f = input.files?.[0];
        if (f) actions.openKey(which, f);
        input.value = '';
      });
      const b = noFocusOnClick(h('button', { type: 'button', class: 'small', title: 'Open an SVG file as this key' }, 'Open…'));
      b.addEventListener('click', () => input.click());
      // A glyph of a local font file: the character typed beside the button.
      const char = h('input', { type: 'text', value: which === 'a' ? 'G' : 'G', maxlength: 2, size: 2, 'aria-label': 'Character', 'data-testid': `morph-char-${which}`, title: 'The character to take from the font' });
      const fontInput = h('input', { type: 'file', accept: '.ttf,.otf,.woff,font/ttf,font/otf,font/woff', hidden: true, 'data-testid': `morph-font-${which}` });
      fontInput.addEventListener('change', () => {
        const f = fontInput.files?.[0];
        if (f) actions.openFont(which, f, char.value);
        fontInput.value = '';
      });
      const fb = noFocusOnClick(h('button', { type: 'button', class: 'small', title: 'Take a glyph of a font file (TrueType, OpenType, WOFF) as this key' }, 'Font glyph…'));
      fb.addEventListener('click', () => fontInput.click());
      return h('span', {}, b, input, ' ', fb, ' ', char, fontInput);
    };
    const keys = h(
      'div',
      { class: 'morph-keys' },
      h('label', {}, 'First key (blue)'),
      this.selects.a,
      openButton('a'),
      h('label', {}, 'Second key (orange)'),
      this.selects.b,
      openButton('b'),
    );

    const interp = h('div', { class: 'segmented', role: 'group', 'aria-label': 'Interpolation' });
    for (const [m, label, title] of [
      ['linear', 'Linear', 'Control points and knots travel on straight lines (the paper, §2)'],
      ['intrinsic', 'Intrinsic', 'Edge lengths and turning angles of the control polygon are interpolated (Sederberg et al. 1993): bends and turns do not shrink'],
    ] as const) {
      const b = noFocusOnClick(h('button', { type: 'button', 'data-interpolation': m, title, 'aria-pressed': 'false' }, label));
      b.addEventListener('click', () => actions.setInterpolation(m));
      this.interp.set(m, b);
      interp.append(b);
    }

    this.slider = h('input', { type: 'range', min: 0, max: 1000, step: 1, class: 'morph-slider', 'data-testid': 'morph-slider', 'aria-label': 't' });
    this.slider.addEventListener('input', () => actions.seek(Number(this.slider.value) / 1000, true));
    this.slider.addEventListener('change', () => actions.seek(Number(this.slider.value) / 1000, false));
    this.play = noFocusOnClick(h('button', { type: 'button', class: 'small', 'data-testid': 'morph-play', title: 'Play the blend there and back (Space)' }, 'Play'));
    this.play.addEventListener('click', () => actions.togglePlay());

    const layers = h('div', {});
    for (const [name, label, title] of [
      ['onion', 'Onion skin', 'The two keys as dashed outlines: first blue, second orange'],
      ['lines', 'Correspondence', 'A line from every anchor of the first key to the point of the second it blends into'],
    ] as const) {
      const box = h('input', { type: 'checkbox', checked: true, 'data-layer': name });
      box.addEventListener('change', () => actions.setLayer(name, box.checked));
      this.boxes.set(name, box);
      layers.append(h('label', { title }, box, ` ${label}`));
    }

    const clear = noFocusOnClick(h('button', { type: 'button', class: 'small', title: 'Remove every pin (undoable)' }, 'Clear pins'));
    clear.addEventListener('click', () => actions.clearPins());
    const exportSmil = noFocusOnClick(h('button', { type: 'button', class: 'small', 'data-testid': 'morph-export-animated', title: 'An SVG that plays the blend with SMIL, no script' }, 'Animated SVG'));
    exportSmil.addEventListener('click', () => actions.exportAnimated('smil'));
    const exportCss = noFocusOnClick(h('button', { type: 'button', class: 'small', title: 'An SVG that plays the blend with CSS keyframes of d: path(…)' }, 'CSS keyframes'));
    exportCss.addEventListener('click', () => actions.exportAnimated('css'));
    const exportFrames = noFocusOnClick(h('button', { type: 'button', class: 'small', 'data-testid': 'morph-export-frames', title: '11 frames at t = 0, 0.1, …, 1 side by side in one SVG' }, 'Frames'));
    exportFrames.addEventListener('click', () => actions.exportFrames());

    this.sections = [
      section('Keys', keys, this.error),
      section('Blend', interp, h('div', {}, h('span', {}, 't = '), this.tLabel, ' ', this.play), this.slider),
      section('Show', layers),
      section('Pins', h('p', { class: 'hint' }, 'Drag from a point of the first key to where it should land on the second. Drag a pin’s end to move it.'), clear),
      section('Morph', this.info.el),
      section('Export', h('div', {}, exportSmil, ' ', exportCss, ' ', exportFrames)),
    ];
  }

  setKeys(a: KeyChoice, b: KeyChoice): void {
    for (const [which, k] of [['a', a], ['b', b]] as const) {
      const s = this.selects[which];
      const fileOption = s.querySelector('option[value="file"]') as HTMLOptionElement;
      fileOption.textContent = k.source === 'file' ? (k.name ?? 'A file') : 'A file…';
      s.value = k.source;
    }
  }

  setInterpolation(m: MorphInterpolation): void {
    for (const [k, b] of this.interp) b.setAttribute('aria-pressed', String(k === m));
  }

  setT(t: number): void {
    this.slider.value = String(Math.round(t * 1000));
    this.tLabel.textContent = t.toFixed(3);
  }

  setPlaying(on: boolean): void {
    this.play.textContent = on ? 'Pause' : 'Play';
    this.play.setAttribute('aria-pressed', String(on));
  }

  setInfo(info: { contours: number; work: number; ms: number; frameMs: number; pins: number } | null, error: string | null): void {
    this.error.hidden = !error;
    this.error.textContent = error ?? '';
    this.info.set('Contours', info ? String(info.contours) : '—');
    this.info.set('Work', info ? info.work.toPrecision(4) : '—', 'Least work of stretching, bending, kinking and travel (Sederberg & Greenwood §5)');
    this.info.set('Correspondence', info ? `${info.ms.toFixed(1)} ms` : '—');
    this.info.set('Frame', info ? `${info.frameMs.toFixed(3)} ms` : '—');
    this.info.set('Pins', info ? String(info.pins) : '—');
  }
}
