import type { Command } from '../../app/history.js';
import type { CurveSnapshot, EditCurves } from './curves.js';

/**
 * An undoable change of a document's Edit curves, as the curves before and after it (exact: undo
 * restores the very coordinates). `applied` lets the mode redraw and autosave.
 */
export class CurvesCommand implements Command {
  constructor(
    readonly label: string,
    private readonly curves: EditCurves,
    private readonly before: CurveSnapshot[],
    private readonly after: CurveSnapshot[],
    private readonly applied: (curves: EditCurves) => void,
  ) {}

  do(): void {
    this.curves.restore(this.after);
    this.applied(this.curves);
  }

  undo(): void {
    this.curves.restore(this.before);
    this.applied(this.curves);
  }
}
