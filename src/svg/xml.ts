import { DOMParser } from '@xmldom/xmldom';
import { SplinekitError } from '../core/errors.js';

/**
 * Parses XML text (internal entities already expanded, see entities.ts) with xmldom; malformed
 * markup throws SplinekitError('invalid-svg') naming `name` and the parser's reason. Shared by
 * parseSVG and SvgDocument.fromTransfer, so markup written by one reads back the same in the other.
 */
export function parseXML(text: string, name: string): Document {
  try {
    const dom = new DOMParser({
      onError: (level: string, message: string) => {
        if (level !== 'warning') throw new Error(message);
      },
    }).parseFromString(text, 'image/svg+xml');
    if (!dom.documentElement) throw new Error('no root element');
    return dom as unknown as Document;
  } catch (err) {
    const reason = (err instanceof Error ? err.message : String(err))
      .split('\n')[0]
      .replace(/^.*caused Error: /, '')
      .replace(/^element parse error: Error: /, '');
    throw new SplinekitError('invalid-svg', `${name}: not well-formed XML: ${reason}`, { cause: err });
  }
}
