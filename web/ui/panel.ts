import { h } from './dom.js';
import { MOD } from './toolbar.js';

/** The side panel: a title for the active mode and a body the mode fills. */
export class SidePanel {
  readonly el: HTMLElement;
  readonly body: HTMLElement;
  private readonly title = h('h2', { class: 'panel-title' });
  private readonly subtitle = h('p', { class: 'panel-subtitle' });
  private readonly modeKeys = h('dl', { class: 'facts keys mode-keys', 'data-testid': 'mode-keys' });

  constructor() {
    this.body = h('div', { class: 'panel-body' });
    this.el = h('aside', { class: 'panel', 'aria-label': 'Side panel' }, h('div', { class: 'panel-head' }, this.title, this.subtitle), this.body, shortcuts(this.modeKeys));
  }

  setHeading(title: string, subtitle: string): void {
    this.title.textContent = title;
    this.subtitle.textContent = subtitle;
  }

  /** The active mode's keys, shown above the editor's in the Keys section. */
  setModeKeys(keys: readonly (readonly [string, string])[]): void {
    this.modeKeys.hidden = keys.length === 0;
    this.modeKeys.replaceChildren(...keys.flatMap(([k, what]) => [h('dt', {}, k), h('dd', {}, what)]));
  }
}

/** A titled section of the panel. */
export function section(title: string, ...content: HTMLElement[]): HTMLElement {
  return h('section', { class: 'panel-section' }, h('h3', {}, title), ...content);
}

/** A two-column list of name/value rows; returns the element and a setter per row. */
export function facts(names: string[]): { el: HTMLElement; set: (name: string, value: string, title?: string) => void } {
  const values = new Map<string, HTMLElement>();
  const el = h('dl', { class: 'facts' });
  for (const name of names) {
    const dd = h('dd', { 'data-fact': name });
    values.set(name, dd);
    el.append(h('dt', {}, name), dd);
  }
  return {
    el,
    set(name, value, title) {
      const dd = values.get(name)!;
      dd.textContent = value;
      if (title) dd.title = title;
      else dd.removeAttribute('title');
    },
  };
}

/** The active mode's keys, then the view's and the editor's, always at the bottom of the panel. */
function shortcuts(modeKeys: HTMLElement): HTMLElement {
  const keys: [string, string][] = [
    ['Drag · Space+drag · middle button', 'pan'],
    ['Wheel · pinch', 'zoom at the cursor'],
    ['F · 1 · + · −', 'fit, 100%, zoom in, out'],
    ['H', 'show or hide the points'],
    [`${MOD}Z · ${MOD}Shift+Z`, 'undo, redo'],
    [`${MOD}O · ${MOD}S`, 'open, export'],
  ];
  return h(
    'details',
    { class: 'panel-section shortcuts' },
    h('summary', {}, 'Keys'),
    modeKeys,
    h('dl', { class: 'facts keys' }, ...keys.flatMap(([k, what]) => [h('dt', {}, k), h('dd', {}, what)])),
  );
}
