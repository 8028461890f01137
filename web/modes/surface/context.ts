import type { MeshInfo, TraceOptions } from '../../../src/index.js';
import type { InFlight } from '../../app/in-flight.js';
import type { ModeContext } from '../../app/modes.js';
import type { View3D } from '../../view3d/view3d.js';
import type { SurfaceClient } from './client.js';
import type { SurfaceCommandTarget, SurfaceSelection } from './commands.js';
import type { SurfaceDrawing } from './drawing.js';
import type { SurfaceSession } from './session.js';
import type { SurfacePanel, SurfaceTool } from './surface-panel.js';
import type { SurfacePrefs } from './storage.js';

/** The mesh shown: what the core reported, its size, and how long loading took. */
export interface ShownMeshInfo {
  info: MeshInfo;
  /** Bounding-box diagonal. */
  scale: number;
  /** Milliseconds to load it (in the worker): to shown, then to ready. */
  loadMs: number;
  /** Its search structures are built (before, traces wait for them in the worker). */
  ready: boolean;
}

/**
 * What Surface mode's parts (mesh sessions, trace cache, edits, SVG placement, gestures, picking)
 * share: the mode implements it and hands itself to each part, so that each part reads the state
 * it needs here and owns only its own.
 */
export interface SurfaceContext extends SurfaceCommandTarget {
  /** The editor's context while the mode is active, else null. */
  readonly ctx: ModeContext | null;
  /** The 3D view (null until the mode was first activated). */
  readonly view: View3D | null;
  readonly panel: SurfacePanel | null;
  /** The surface worker's client. */
  readonly client: SurfaceClient;
  /** The mode's work under way (loads, requests, queued edits): the test hook waits on it. */
  readonly work: InFlight;
  /** The session shown (mesh and drawing), or null. */
  readonly session: SurfaceSession | null;
  readonly mesh: ShownMeshInfo | null;
  /** Counts mesh loads: replies for an older mesh are dropped. */
  readonly generation: number;
  /** The shown session's drawing (empty without one). */
  readonly drawing: SurfaceDrawing;
  readonly selection: SurfaceSelection | null;
  readonly prefs: SurfacePrefs;
  /** The spline that clicks extend, or null. */
  readonly drawingId: number | null;
  /** What a drag on the mesh does. */
  readonly tool: SurfaceTool;
  /** The trace options the preferences ask for. */
  traceOptions(): TraceOptions;
  setSelection(selection: SurfaceSelection | null): void;
  setPrefs(change: Partial<SurfacePrefs>): void;
  /** Reports a failure in the status bar. */
  setError(message: string): void;
  requestDraw(): void;
  refreshPanel(): void;
  refreshStatus(): void;
}

export { messageOf } from '../../app/errors.js';
