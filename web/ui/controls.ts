import { h, noFocusOnClick } from './dom.js';

/** Small panel controls shared by the modes' side panels. */

/** A row of toggle buttons, one pressed (aria-pressed): returns the element and a setter. */
export function segmented<T extends string>(label: string, items: [T, string, string][], onPick: (v: T) => void): { el: HTMLElement; set(v: T): void } {
  const el = h('div', { class: 'segmented', role: 'group', 'aria-label': label });
  const buttons = new Map<T, HTMLButtonElement>();
  for (const [value, text, title] of items) {
    const b = noFocusOnClick(h('button', { type: 'button', title, 'aria-pressed': 'false', 'data-value': value }, text));
    b.addEventListener('click', () => onPick(value));
    buttons.set(value, b);
    el.append(b);
  }
  return {
    el,
    set(v) {
      for (const [k, b] of buttons) b.setAttribute('aria-pressed', String(k === v));
    },
  };
}

/** A button that does not take the focus on click. */
export function button(text: string, title: string, onclick: () => void, cls = 'small', testid?: string): HTMLButtonElement {
  const b = noFocusOnClick(h('button', { type: 'button', class: cls, title, 'data-testid': testid }, text));
  b.addEventListener('click', onclick);
  return b;
}

/** A hidden file input that hands over the chosen file (and forgets it, so the same file can be chosen again). */
export function fileInput(accept: string, testid: string, onFile: (f: File) => void): HTMLInputElement {
  const input = h('input', { type: 'file', accept, hidden: true, 'data-testid': testid });
  input.addEventListener('change', () => {
    const f = input.files?.[0];
    input.value = '';
    if (f) onFile(f);
  });
  return input;
}
