import type { Command } from '../../app/history.js';
import type { SurfaceDrawing } from './drawing.js';
import type { SurfaceSession } from './session.js';

/** What is selected: a spline, and optionally one of its control points. */
export interface SurfaceSelection {
  spline: number;
  point: number | null;
}

/** Who shows selections and meshes for the commands (the surface mode). */
export interface SurfaceCommandTarget {
  select(session: SurfaceSession, selection: SurfaceSelection | null): void;
  showSession(session: SurfaceSession | null): void;
}

/**
 * One undoable edit of a drawing: the drawing before and after (immutable values, so this is
 * exact and cheap), and what to select after do and after undo.
 */
export class DrawingCommand implements Command {
  constructor(
    readonly label: string,
    private readonly target: SurfaceCommandTarget,
    private readonly session: SurfaceSession,
    private readonly before: SurfaceDrawing,
    private readonly after: SurfaceDrawing,
    private readonly selection: { do?: SurfaceSelection | null; undo?: SurfaceSelection | null } = {},
  ) {}

  do(): void {
    this.session.setDrawing(this.after);
    if (this.selection.do !== undefined) this.target.select(this.session, this.selection.do);
  }

  undo(): void {
    this.session.setDrawing(this.before);
    if (this.selection.undo !== undefined) this.target.select(this.session, this.selection.undo);
  }
}

/** Opens a mesh (with its drawing); undo goes back to the previous mesh and its drawing. */
export class OpenMeshCommand implements Command {
  readonly label: string;

  constructor(
    private readonly target: SurfaceCommandTarget,
    private readonly previous: SurfaceSession | null,
    private readonly next: SurfaceSession,
  ) {
    this.label = `Open ${next.file}`;
  }

  do(): void {
    this.target.showSession(this.next);
  }

  undo(): void {
    this.target.showSession(this.previous);
  }
}
