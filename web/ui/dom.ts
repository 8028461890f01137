type Child = Node | string | null | undefined | false;
type Props = Record<string, string | number | boolean | EventListener | undefined>;

/**
 * Creates an element: h('button', { class: 'x', onclick: fn, title: 't' }, 'Label').
 * Props starting with "on" become listeners, `true` booleans become empty attributes.
 */
export function h<K extends keyof HTMLElementTagNameMap>(tag: K, props: Props = {}, ...children: Child[]): HTMLElementTagNameMap[K] {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (v === undefined || v === false) continue;
    if (k.startsWith('on') && typeof v === 'function') el.addEventListener(k.slice(2), v);
    else el.setAttribute(k, v === true ? '' : String(v));
  }
  for (const c of children) if (c !== null && c !== undefined && c !== false) el.append(c);
  return el;
}

/** An inline SVG icon from path data on a 16×16 grid (stroked, currentColor). */
export function icon(d: string): SVGSVGElement {
  const ns = 'http://www.w3.org/2000/svg';
  const svg = document.createElementNS(ns, 'svg');
  svg.setAttribute('viewBox', '0 0 16 16');
  svg.setAttribute('class', 'icon');
  svg.setAttribute('aria-hidden', 'true');
  const path = document.createElementNS(ns, 'path');
  path.setAttribute('d', d);
  svg.appendChild(path);
  return svg;
}

/** Icons used by the toolbar (hand-drawn for this project). */
export const ICONS = {
  open: 'M2 4.5h4l1.5 1.5H14v6.5H2z',
  export: 'M8 2v8M4.5 6.5 8 10l3.5-3.5M3 13.5h10',
  undo: 'M5.5 4 2.5 7l3 3M2.5 7H10a3.5 3.5 0 0 1 0 7H7',
  redo: 'M10.5 4l3 3-3 3M13.5 7H6a3.5 3.5 0 0 0 0 7h3',
  fit: 'M2 5.5V2h3.5M10.5 2H14v3.5M14 10.5V14h-3.5M5.5 14H2v-3.5',
  overlay: 'M3 13 7 5l6 8M1.5 11.5h3v3h-3zM5.5 3.5h3v3h-3zM11.5 11.5h3v3h-3z',
  zoomIn: 'M6.5 2.5a4 4 0 1 0 0 8a4 4 0 1 0 0-8M6.5 4.5v4M4.5 6.5h4M9.5 9.5 14 14',
  zoomOut: 'M6.5 2.5a4 4 0 1 0 0 8a4 4 0 1 0 0-8M4.5 6.5h4M9.5 9.5 14 14',
};

/**
 * Keeps a pointer click on a control from taking the keyboard focus (keys such as Space or F
 * then keep going to the canvas instead of re-pressing the button); Tab still reaches it.
 */
export function noFocusOnClick<T extends HTMLElement>(el: T): T {
  el.addEventListener('mousedown', (e) => e.preventDefault());
  return el;
}
