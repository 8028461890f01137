import { anchorJunction, type ContinuityKind, type MeshPoint } from '../../src/index.js';
import type { EditTestState } from '../modes/edit/edit-mode.js';
import type { MorphTestState } from '../modes/morph/morph-mode.js';
import type { SkinTestState } from '../modes/skin/skin-mode.js';
import type { Skin3DTestState } from '../modes/skin3d/skin3d-mode.js';
import type { SurfaceTestState } from '../modes/surface/surface-mode.js';
import type { Editor } from './editor.js';

/** A read-only window into the editor for end-to-end tests (window.splinekitEditor). */
export interface EditorTestHook {
  /** Resolves when the starting sample is drawn (or its loading failed and says so). */
  ready: Promise<void>;
  state(): {
    file: string | null;
    elements: number;
    splines: number;
    segments: number;
    overlay: boolean;
    /** Anchors the overlay draws. */
    anchors: number;
    error: string | null;
    importMs: number | null;
    selection: { spline: number; anchor: number; kind: ContinuityKind | null } | null;
    canUndo: boolean;
    canRedo: boolean;
    /** How many times a document has been shown (opened, undone to, reverted): tells a reopened file from the one before. */
    documentsShown: number;
  };
  /** Where an anchor is on screen (client pixels), to click it like a user would. */
  anchorOnScreen(spline: number, anchor: number): { x: number; y: number } | null;
  /** Where a document point is on screen (client pixels). */
  docToScreen(x: number, y: number): { x: number; y: number };
  /**
   * Shows the document's frame at client pixel (x, y), `width` pixels wide (integers keep its
   * edges on pixel boundaries), and resolves once that has been drawn; returns the frame's size.
   */
  placeFrame(x: number, y: number, width: number): Promise<{ width: number; height: number }>;
  /** The document's frame [x, y, w, h] (its viewBox, else its size), or null. */
  frame(): [number, number, number, number] | null;
  /** The drawing's bounds at import [xmin, ymin, xmax, ymax], or null. */
  bounds(): [number, number, number, number] | null;
  /** Skin mode: rig, pose (checksum of the posed points), keyframes, layers. */
  skin(): SkinTestState;
  /** Where skin handle `index` is drawn (client pixels), or null. */
  skinHandleOnScreen(index: number): { x: number; y: number } | null;
  /** The skin gizmo of the selected handle (client pixels), or null. */
  skinGizmoOnScreen(): { center: { x: number; y: number }; knob: { x: number; y: number }; ring: number } | null;
  /** Surface mode. */
  surface: SurfaceTestHook;
  /** 3D Skin mode. */
  skin3d: Skin3DTestHook;
  /** Edit mode: tool, settings, curves, selection, the active window's preview. */
  edit(): EditTestState;
  /** Where control point `point` of Edit curve `curve` is drawn (client pixels), or null. */
  editPointOnScreen(curve: number, point: number): { x: number; y: number } | null;
  /** Where the active window's left or right end is drawn (client pixels), or null. */
  editWindowEndOnScreen(side: 'left' | 'right'): { x: number; y: number } | null;
  /** Morph mode: keys, t, work, pins, a checksum of the in-between. */
  morph(): MorphTestState;
  /** Where matched anchor k of the first ('a') or second ('b') morph key is drawn (client pixels), or null. */
  morphAnchorOnScreen(which: 'a' | 'b', k: number): { x: number; y: number } | null;
}

/** Surface mode's window for tests (window.splinekitEditor.surface). */
export interface SurfaceTestHook {
  /** Resolves when a mesh is shown and no load, edit or trace is under way. */
  ready(): Promise<void>;
  /** Mesh info, splines (JSON and traced polylines), selection, tool, last trace time. */
  state(): SurfaceTestState;
  /** Where a mesh point is on screen (client pixels), and whether the camera sees it. */
  project(p: MeshPoint): { x: number; y: number; visible: boolean } | null;
  /** The mesh point under a client point, or null (off the mesh). */
  meshPointAt(x: number, y: number): MeshPoint | null;
  /** Vertex positions of the given faces, 9 numbers per face (x y z of its 3 vertices). */
  faceVertices(faces: number[]): number[];
}

/** 3D Skin mode's window for tests (window.splinekitEditor.skin3d). */
export interface Skin3DTestHook {
  /** Resolves when a cage is shown and no load or rig build is under way. */
  ready(): Promise<void>;
  state(): Skin3DTestState;
  /** Where a world point is on screen (client pixels), or null (behind the camera). */
  project(x: number, y: number, z: number): { x: number; y: number } | null;
  /** A point on the gizmo's axis handle (client pixels) and the axis's screen direction, or null. */
  gizmoAxis(axis: 'X' | 'Y' | 'Z'): { x: number; y: number; dx: number; dy: number } | null;
  /** The animated glTF the export writes (binary), as plain bytes. */
  gltf(): Promise<number[]>;
}

declare global {
  interface Window {
    splinekitEditor?: EditorTestHook;
  }
}

export function installTestHook(editor: Editor, ready: Promise<void>): void {
  let documentsShown = 0;
  editor.state.events.on('document', () => documentsShown++);
  const hook: EditorTestHook = {
    ready,
    state() {
      const { state, history, overlay } = editor;
      const current = state.current;
      const stats = current?.doc.stats();
      const sel = state.selection;
      let kind: ContinuityKind | null = null;
      if (sel && current) {
        const s = current.doc.splines[sel.spline];
        const j = anchorJunction(s, sel.anchor);
        kind = j < 0 ? null : s.continuity[j].kind;
      }
      return {
        file: current?.file ?? null,
        elements: stats?.elements ?? 0,
        splines: stats?.splines ?? 0,
        segments: stats?.segments ?? 0,
        overlay: state.overlay && overlay.visible,
        anchors: overlay.counts.anchors,
        error: state.error,
        importMs: current?.importMs ?? null,
        selection: sel ? { ...sel, kind } : null,
        canUndo: history.canUndo,
        canRedo: history.canRedo,
        documentsShown,
      };
    },
    anchorOnScreen(spline, anchor) {
      const p = editor.doc?.splines[spline]?.points;
      if (!p || 2 * anchor + 1 >= p.length) return null;
      const [sx, sy] = editor.view.toScreen(p[2 * anchor], p[2 * anchor + 1]);
      return client(sx, sy);
    },
    docToScreen(x, y) {
      const [sx, sy] = editor.view.toScreen(x, y);
      return client(sx, sy);
    },
    async placeFrame(x, y, width) {
      const r = editor.view.canvas.getBoundingClientRect();
      editor.view.placeFrame(x - r.left, y - r.top, width);
      await editor.view.nextFrame();
      const frame = editor.doc?.frame ?? [0, 0, 1, 1];
      return { width, height: (width * frame[3]) / frame[2] };
    },
    frame() {
      const f = editor.doc?.frame;
      return f ? [...f] : null;
    },
    bounds() {
      const b = editor.doc?.bounds;
      return b ? [...b] : null;
    },
    skin() {
      return editor.skin.testState();
    },
    skinHandleOnScreen(index) {
      const at = editor.skin.handleOnCanvas(index);
      return at ? client(at[0], at[1]) : null;
    },
    skinGizmoOnScreen() {
      const g = editor.skin.gizmoOnCanvas();
      return g ? { center: client(...g.center), knob: client(...g.knob), ring: g.ring } : null;
    },
    edit: () => editor.edit.testState(),
    editPointOnScreen(curve, point) {
      const at = editor.edit.pointOnCanvas(curve, point);
      return at ? client(at[0], at[1]) : null;
    },
    editWindowEndOnScreen(side) {
      const at = editor.edit.windowEndOnCanvas(side);
      return at ? client(at[0], at[1]) : null;
    },
    morph() {
      return editor.morph.testState();
    },
    morphAnchorOnScreen(which, k) {
      const at = editor.morph.anchorOnCanvas(which, k);
      return at ? client(at[0], at[1]) : null;
    },
    skin3d: Object.freeze({
      ready: () => editor.skin3d.ready(),
      state: () => editor.skin3d.testState(),
      project(x: number, y: number, z: number) {
        const at = editor.skin3d.project(x, y, z);
        return at ? canvas3dClient(editor.skin3d.view?.canvas, at.sx, at.sy) : null;
      },
      gizmoAxis(axis: 'X' | 'Y' | 'Z') {
        const at = editor.skin3d.gizmoAxisOnCanvas(axis);
        return at ? { ...canvas3dClient(editor.skin3d.view?.canvas, at.sx, at.sy), dx: at.dx, dy: at.dy } : null;
      },
      gltf: async () => [...new Uint8Array(await editor.skin3d.gltfBytes())],
    }),
    surface: Object.freeze({
      ready: () => editor.surface.ready(),
      state: () => editor.surface.testState(),
      project(p: MeshPoint) {
        const at = editor.surface.projectOnCanvas(p);
        return at ? { ...surfaceClient(at.x, at.y), visible: at.visible } : null;
      },
      meshPointAt(x: number, y: number) {
        const r = editor.surface.canvas?.getBoundingClientRect();
        return r ? editor.surface.meshPointOnCanvas(x - r.left, y - r.top) : null;
      },
      faceVertices: (faces: number[]) => editor.surface.faceVertices(faces),
    }),
  };
  /** 3D canvas pixels → client pixels. */
  function canvas3dClient(canvas: HTMLCanvasElement | null | undefined, sx: number, sy: number): { x: number; y: number } {
    const r = canvas?.getBoundingClientRect();
    return { x: (r?.left ?? 0) + sx, y: (r?.top ?? 0) + sy };
  }
  function surfaceClient(sx: number, sy: number): { x: number; y: number } {
    return canvas3dClient(editor.surface.canvas, sx, sy);
  }
  /** Canvas pixels → client pixels. */
  function client(sx: number, sy: number): { x: number; y: number } {
    const r = editor.view.canvas.getBoundingClientRect();
    return { x: r.left + sx, y: r.top + sy };
  }
  window.splinekitEditor = Object.freeze(hook);
}
