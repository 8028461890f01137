import type { Command } from '../../app/history.js';
import type { SkinSession } from './session.js';
import type { SkinSpec } from './spec.js';

/**
 * One undoable skin edit: the spec before and after (specs are immutable values, so this is
 * exact and cheap). Optionally selects a handle after do/undo (e.g. the one just added).
 */
export class SpecCommand implements Command {
  constructor(
    readonly label: string,
    private readonly session: SkinSession,
    private readonly before: SkinSpec,
    private readonly after: SkinSpec,
    private readonly selection: { do?: number | null; undo?: number | null } = {},
  ) {}

  do(): void {
    this.session.apply(this.after);
    if (this.selection.do !== undefined) this.session.select(this.selection.do);
  }

  undo(): void {
    this.session.apply(this.before);
    if (this.selection.undo !== undefined) this.session.select(this.selection.undo);
  }
}
