import { h } from '../ui/dom.js';

/** Offers `data` (text, or bytes) as a file download (an SVG unless told otherwise). */
export function download(data: string | ArrayBuffer, file: string, type = 'image/svg+xml'): void {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const a = h('a', { href: url, download: file });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/** `name.svg` → `name-<suffix>.svg`. */
export function derivedName(file: string, suffix: string): string {
  const base = file.replace(/\.svg$/i, '');
  return `${base}${suffix ? `-${suffix}` : ''}.svg`;
}
