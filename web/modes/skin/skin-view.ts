import { poseAt, type AffineMatrix, type SvgDocument, affine } from '../../../src/index.js';
import type { ModeContext } from '../../app/modes.js';
import { CurveLayers, curveSamples, type CurveLayerData } from './curve-layers.js';
import type { Gesture } from './gestures.js';
import { HandlesLayer, type HandleMark } from './handles-layer.js';
import { SAMPLES } from './rig-build.js';
import type { SkinSession } from './session.js';
import { SkinPanel, type LayerFlags, type SkinPanelActions, type SkinTool } from './skin-panel.js';
import { EMPTY_SPEC, keyframeAt } from './spec.js';
import { Timeline, type TimelineActions } from './timeline.js';

/** What the skin view shows: the session and the mode's tool, layers and gesture. */
export interface SkinViewState {
  session: SkinSession | null;
  tool: SkinTool;
  layers: LayerFlags;
  gesture: Gesture | null;
  /** Rotation and scale shown by the gizmo during a gesture. */
  readout: string | null;
  playing: boolean;
}

/** Whether the view shows the posed drawing (Pose tool with a rig) rather than the rest. */
export function showsPose(st: SkinViewState): boolean {
  return st.tool === 'pose' && st.session?.points != null && st.session.rig !== null;
}

/**
 * Everything skin mode shows while active: the drawing (posed or at rest) in the editor's view,
 * the curve layers and handles over it, the side panel and the timeline in the dock.
 */
export class SkinView {
  readonly panel: SkinPanel;
  readonly timeline: Timeline;
  readonly curves: CurveLayers;
  readonly handles: HandlesLayer;
  /** The posed points last drawn (null: the rest drawing; undefined: nothing yet). */
  private shownPoints: Float64Array | null | undefined = undefined;
  /** The posed drawing shown, written over in place for every pose of the same rig (not copied per frame). */
  private posed: { rig: object; doc: SvgDocument } | null = null;

  constructor(
    private readonly ctx: ModeContext,
    panelActions: SkinPanelActions,
    timelineActions: TimelineActions,
  ) {
    this.panel = new SkinPanel(panelActions);
    ctx.panel.append(...this.panel.sections);
    this.timeline = new Timeline(timelineActions);
    ctx.dock.append(this.timeline.el);
    this.curves = new CurveLayers(ctx.view);
    this.handles = new HandlesLayer(ctx.view);
  }

  /** Whether the drawing shown was drawn live (a still draw writes it again exactly). */
  private shownLive = false;

  /** Draws the drawing again on the next draw (another document, control points turned on). */
  invalidate(): void {
    this.shownPoints = undefined;
  }

  /** The session's document with `points` in its splines: one copy per rig, its points replaced. */
  private posedDocument(s: SkinSession, points: Float64Array): SvgDocument {
    const rig = s.rig!.rig;
    const p = this.posed;
    if (p?.rig !== rig || p.doc.splines.reduce((n, sp) => n + sp.points.length, 0) !== points.length) {
      this.posed = { rig, doc: rig.posedDocument(points) };
      return this.posed.doc;
    }
    let at = 0;
    for (const sp of p.doc.splines) {
      sp.points.set(points.subarray(at, at + sp.points.length));
      at += sp.points.length;
    }
    return p.doc;
  }

  /** The view moved: lines keep their pixel widths, handles their places. */
  viewChanged(): void {
    this.curves.viewChanged();
    this.handles.draw();
  }

  draw(st: SkinViewState): void {
    const { ctx } = this, s = st.session, doc = s?.doc ?? null;
    if (!s || !doc) {
      this.curves.update(null);
      this.handles.set([], null, null);
      this.refreshTimeline(st);
      return;
    }
    const posed = showsPose(st);
    const points = posed ? s.points : null;
    // Live while a handle is dragged or the timeline plays: a still draw follows when it ends.
    const live = st.gesture !== null || st.playing;
    if (points !== this.shownPoints || (!live && this.shownLive)) {
      this.shownPoints = points;
      this.shownLive = live;
      const shown: SvgDocument = points ? this.posedDocument(s, points) : doc;
      ctx.view.showDrawing(shown, { live });
      // The control points follow the pose when shown (H), moved in place.
      if (ctx.state.overlay) ctx.overlay.update(shown);
    }

    // While a handle is dragged or the timeline plays, the errors shown are the last measured.
    const errors = !posed ? null : st.gesture || st.playing ? s.errorsSoFar() : s.errors();
    const data: CurveLayerData = { doc, perCurve: SAMPLES, target: null, heat: null, naive: null, field: null };
    if (posed) {
      if (st.layers.target) {
        data.target = s.targetField();
        if (st.layers.heat) data.heat = errors?.fit.perCurve ?? null;
      }
      if (st.layers.naive) data.naive = s.naivePoints();
    }
    if (st.layers.field && s.selected !== null) {
      const weights = s.handleWeights(s.selected);
      const positions = points ? curveSamples(doc, points, SAMPLES) : s.restSamples();
      if (weights && positions) data.field = { positions, weights };
    }
    this.curves.update(data);

    const spec = s.spec, g = st.gesture;
    const marks: HandleMark[] = spec.handles.map((h, i) => {
      if (g?.kind === 'rest' && g.id === h.id) return { id: h.id, x: g.x, y: g.y, label: String(i + 1) };
      const [x, y] = st.tool === 'pose' ? affine.apply(spec.pose[i], h.x, h.y) : [h.x, h.y];
      return { id: h.id, x, y, label: String(i + 1) };
    });
    const si = s.indexOf(s.selected);
    const gizmo = st.tool === 'pose' && si >= 0 ? { id: spec.handles[si].id, x: marks[si].x, y: marks[si].y, angle: affine.angleOf(spec.pose[si]), readout: st.readout } : null;
    this.handles.set(marks, s.selected, gizmo);
    this.panel.setErrors(errors, doc.size);
    this.refreshTimeline(st);
  }

  refreshPanel(st: SkinViewState): void {
    const s = st.session, spec = s?.spec ?? EMPTY_SPEC;
    this.panel.setTool(st.tool, spec.handles.length);
    this.panel.setSpec({
      handles: spec.handles.length,
      weights: spec.weights,
      flexible: spec.flexible,
      selected: s && s.selected !== null ? s.indexOf(s.selected) + 1 : null,
      posed: !spec.pose.every((m) => affine.isIdentity(m)),
    });
    const keyed = spec.keyframes.length >= 2;
    this.panel.setExport(s?.points != null, keyed, keyed ? 'Download the keyframed animation as an SVG that plays by itself (SMIL, no script)' : 'Key at least two poses on the timeline first (I)');
  }

  refreshTimeline(st: SkinViewState): void {
    const s = st.session, spec = s?.spec ?? EMPTY_SPEC, time = s?.time ?? 0;
    // "Unkeyed": the pose differs from what the animation (or the rest, without keys) has here.
    const expected: readonly AffineMatrix[] | null = spec.keyframes.length > 0 ? poseAt(spec.keyframes, time) : null;
    const unkeyed = spec.handles.length > 0 && (expected ? !spec.pose.every((m, i) => affine.sameMatrix(m, expected[i], 1e-9)) : !spec.pose.every((m) => affine.isIdentity(m)));
    this.timeline.update({
      duration: spec.duration,
      time,
      keyframes: spec.keyframes.map((k) => k.time),
      playing: st.playing,
      canKey: spec.handles.length > 0,
      keyHere: keyframeAt(spec, time),
      unkeyed,
    });
  }

  dispose(): void {
    this.timeline.el.remove();
    this.curves.dispose();
    this.handles.dispose();
  }
}
