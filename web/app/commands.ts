import { junctionAnchor, type ContinuityKind, type SvgDocument } from '../../src/index.js';
import type { Command } from './history.js';
import type { EditorState, LoadedDocument } from './state.js';

/** Replaces the document; undo brings the previous one back (with its edits). */
export class OpenDocumentCommand implements Command {
  readonly label: string;
  private readonly previous: LoadedDocument | null;

  constructor(
    private readonly state: EditorState,
    private readonly next: LoadedDocument,
  ) {
    this.previous = state.current;
    this.label = `Open ${next.file}`;
  }

  do(): void {
    this.state.setDocument(this.next);
  }
  undo(): void {
    this.state.setDocument(this.previous);
  }
}

/**
 * Overrides the continuity tag of one junction. The tag's measured ratio and angle stay as they
 * are: they describe the geometry, the kind says what later edits must preserve.
 */
export class SetContinuityCommand implements Command {
  readonly label: string;
  private readonly before: ContinuityKind;

  constructor(
    private readonly state: EditorState,
    private readonly doc: SvgDocument,
    private readonly spline: number,
    private readonly junction: number,
    private readonly kind: ContinuityKind,
  ) {
    const tag = doc.splines[spline]?.continuity[junction];
    if (!tag) throw new RangeError(`no junction ${junction} on spline ${spline}`);
    this.before = tag.kind;
    this.label = `Set continuity to ${kind}`;
  }

  do(): void {
    this.set(this.kind);
  }
  undo(): void {
    this.set(this.before);
  }

  private set(kind: ContinuityKind): void {
    this.doc.splines[this.spline].continuity[this.junction].kind = kind;
    this.state.continuityChanged(this.doc, this.spline);
    // Show where the change happened (also on undo/redo, when the user may have moved on).
    if (this.doc === this.state.doc) {
      this.state.select({ spline: this.spline, anchor: junctionAnchor(this.doc.splines[this.spline], this.junction) });
    }
  }
}
