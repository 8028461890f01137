import type { Command } from '../../app/history.js';

/** What a spec command acts on: a session that takes a whole spec and selects a handle by id. */
export interface SpecTarget<S> {
  apply(spec: S): void;
  select(id: number | null): void;
}

/**
 * One undoable skin edit (2D or 3D): the spec before and after (specs are immutable values, so
 * this is exact and cheap). Optionally selects a handle after do/undo (e.g. the one just added).
 */
export class SpecCommand<S> implements Command {
  constructor(
    readonly label: string,
    private readonly session: SpecTarget<S>,
    private readonly before: S,
    private readonly after: S,
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
