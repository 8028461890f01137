// Small pieces of the editor (web/) that its modes share and that run without a browser: the
// cubic point kernel both 2D drawing paths use, Surface mode's list of mesh files, the in-flight tracker the test hook waits on, and
// the request/response worker client (here over a stand-in worker).
import { beforeAll, describe, expect, test } from 'vitest';
import { Bezier, DEFAULT_MAX_BYTES, init, meshFormatOf } from '../../src/index.js';
import { InFlight } from '../../web/app/in-flight.js';
import { WorkerClient } from '../../web/app/worker-client.js';
import { readFile } from '../../web/app/loader.js';
import { MESH_ACCEPT, isMeshFile, surfaceFileLimit } from '../../web/modes/surface/mesh-files.js';
import { cubicPointInto } from '../../web/view2d/cubic.js';
import { cubicAt } from './helpers.js';

beforeAll(async () => {
  await init();
});

const nextTask = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

describe('cubicPointInto', () => {
  test('agrees with the power basis and with the core (Bezier.point), at offsets in a longer array', () => {
    // Two segments sharing an end, x,y pairs: P0 P1 P2 P3 P4 P5 P6.
    const p = Float64Array.from([0, 0, 10, 40, 60, -20, 100, 10, 140, 40, 150, 90, 80, 120]);
    const out = new Float64Array(6);
    for (const seg of [0, 1]) {
      const i = 6 * seg;
      const c = Array.from(p.subarray(i, i + 8));
      for (const t of [0, 0.1, 0.25, 0.5, 0.73, 1]) {
        cubicPointInto(p, i, i + 2, i + 4, i + 6, t, out, 2);
        const power = cubicAt(c, t), core = Bezier.point(c, t);
        expect(out[2]).toBeCloseTo(power[0], 10);
        expect(out[3]).toBeCloseTo(power[1], 10);
        expect(out[2]).toBeCloseTo(core[0], 10);
        expect(out[3]).toBeCloseTo(core[1], 10);
      }
    }
    // The ends are the end points exactly, and nothing else in `out` was written.
    cubicPointInto(p, 6, 8, 10, 12, 1, out, 4);
    expect([out[4], out[5]]).toEqual([80, 120]);
    expect([out[0], out[1]]).toEqual([0, 0]);
  });

  test('a closed spline wraps: the last segment ends on the first point', () => {
    const p = [0, 0, 1, 2, 3, 2, 4, 0, 3, -2, 1, -2]; // 3 segments' worth: 3n = 6 points
    const out = [NaN, NaN];
    cubicPointInto(p, 6, 8, 10, 0, 1, out, 0);
    expect(out).toEqual([0, 0]);
  });
});

describe('InFlight', () => {
  test('idle() waits for tracked promises and hand-begun work, and not for settled ones', async () => {
    const work = new InFlight();
    expect(work.busy).toBe(false);
    await work.idle(); // resolves at once
    let release!: () => void;
    const tracked = work.track(new Promise<void>((resolve) => (release = resolve)));
    const end = work.begin();
    expect(work.size).toBe(2);
    let idle = false;
    void work.idle().then(() => (idle = true));
    release();
    await tracked;
    await nextTask();
    expect(work.size).toBe(1);
    expect(idle).toBe(false);
    end();
    end(); // a second call does nothing
    expect(work.size).toBe(0);
    await nextTask();
    expect(idle).toBe(true);
  });

  test('a rejection ends the work too, and work started in reply keeps it busy', async () => {
    const work = new InFlight();
    let idle = false;
    const first = work.track(Promise.reject(new Error('no')));
    void work.idle().then(() => (idle = true));
    let second: Promise<void> | null = null;
    // What a handler of the first starts in reply counts before the waiters wake.
    await first.catch(() => {
      second = work.track(new Promise<void>((resolve) => setTimeout(resolve, 30)));
    });
    await nextTask();
    expect(idle).toBe(false);
    expect(work.busy).toBe(true);
    await second;
    await nextTask();
    expect(idle).toBe(true);
  });
});

/** Stands in for a dedicated worker: records what it is sent; the test answers by hand. */
class FakeWorker extends EventTarget {
  sent: { message: { id: number; type: string }; transfer: Transferable[] }[] = [];
  terminated = false;
  postMessage(message: { id: number; type: string }, transfer: Transferable[] = []): void {
    this.sent.push({ message, transfer });
  }
  terminate(): void {
    this.terminated = true;
  }
  reply(data: unknown): void {
    this.dispatchEvent(new MessageEvent('message', { data }));
  }
  fail(message: string): void {
    this.dispatchEvent(Object.assign(new Event('error', { cancelable: true }), { message }));
  }
}

type Req = { id: number; type: 'square'; x: number };
type Rep = { id: number; type: 'squared'; y: number } | { id: number; type: 'progress'; fraction: number } | { id: number; type: 'error'; message: string };

describe('WorkerClient', () => {
  function client() {
    const workers: FakeWorker[] = [];
    const c = new WorkerClient<Req, Rep>(() => {
      const w = new FakeWorker();
      workers.push(w);
      return w as unknown as Worker;
    }, 'test');
    return { c, workers };
  }

  test('gives each request an id and settles it by its own reply, in any order; progress does not settle', async () => {
    const { c, workers } = client();
    const buffer = new ArrayBuffer(8);
    const progress: number[] = [];
    const a = c.request({ type: 'square', x: 3 }, [buffer], (r) => r.type === 'progress' && progress.push(r.fraction));
    const b = c.request({ type: 'square', x: 4 });
    expect(workers).toHaveLength(1); // started once, on the first request
    const [sa, sb] = workers[0].sent;
    expect(sa.message).toEqual({ type: 'square', x: 3, id: sa.message.id });
    expect(sa.transfer).toEqual([buffer]);
    expect(sb.message.id).not.toBe(sa.message.id);
    expect(c.size).toBe(2);
    workers[0].reply({ id: sb.message.id, type: 'squared', y: 16 });
    workers[0].reply({ id: sa.message.id, type: 'progress', fraction: 0.5 });
    expect(c.size).toBe(1);
    workers[0].reply({ id: sa.message.id, type: 'squared', y: 9 });
    expect(await a).toEqual({ id: sa.message.id, type: 'squared', y: 9 });
    expect(await b).toEqual({ id: sb.message.id, type: 'squared', y: 16 });
    expect(progress).toEqual([0.5]);
    expect(c.size).toBe(0);
  });

  test('an error reply rejects its request with the message; a late reply to it is ignored', async () => {
    const { c, workers } = client();
    const a = c.request({ type: 'square', x: -1 });
    const id = workers[0].sent[0].message.id;
    workers[0].reply({ id, type: 'error', message: 'negative' });
    await expect(a).rejects.toThrow('negative');
    workers[0].reply({ id, type: 'squared', y: 1 });
    expect(c.size).toBe(0);
  });

  test('terminate() rejects every request waiting with the reason and the next request starts a fresh worker', async () => {
    const { c, workers } = client();
    const a = c.request({ type: 'square', x: 1 }), b = c.request({ type: 'square', x: 2 });
    const reason = new Error('cancelled');
    c.terminate(reason);
    await expect(a).rejects.toBe(reason);
    await expect(b).rejects.toBe(reason);
    expect(workers[0].terminated).toBe(true);
    const d = c.request({ type: 'square', x: 5 });
    expect(workers).toHaveLength(2);
    workers[1].reply({ id: workers[1].sent[0].message.id, type: 'squared', y: 25 });
    expect((await d).type).toBe('squared');
  });

  test('a worker that fails rejects what waits, naming the worker, and is replaced', async () => {
    const { c, workers } = client();
    const a = c.request({ type: 'square', x: 1 });
    workers[0].fail('boom');
    await expect(a).rejects.toThrow('the test worker failed: boom');
    expect(workers[0].terminated).toBe(true);
    void c.request({ type: 'square', x: 2 });
    expect(workers).toHaveLength(2);
  });
});

describe('mesh files', () => {
  test('every extension the editor accepts is a format the package reads, and the accept list is that list', () => {
    const accepted = MESH_ACCEPT.split(',').map((e) => e.replace(/^\./, ''));
    expect(accepted.length).toBeGreaterThanOrEqual(6);
    for (const ext of accepted) {
      expect(meshFormatOf(`mesh.${ext}`)).toBe(ext);
      expect(isMeshFile(`mesh.${ext}`)).toBe(true);
    }
    expect(() => meshFormatOf('mesh.svg')).toThrow();
  });

  test('isMeshFile goes by the last extension, in any case', () => {
    expect(isMeshFile('bunny.OBJ')).toBe(true);
    expect(isMeshFile('scan.v2.glb')).toBe(true);
    expect(isMeshFile('drawing.svg')).toBe(false);
    expect(isMeshFile('ply')).toBe(false);
    expect(isMeshFile('mesh.obj.svg')).toBe(false);
  });

  test('a mesh over the SVG limit (a 2M-triangle scan) is read; an SVG of that size is refused naming the limit', async () => {
    const size = DEFAULT_MAX_BYTES + 1024;
    const mesh = new File([new Uint8Array(size)], 'scan.ply');
    const drawing = new File([new Uint8Array(size)], 'big.svg', { type: 'image/svg+xml' });
    expect((await readFile(mesh, surfaceFileLimit(mesh))).length).toBe(size);
    await expect(readFile(drawing, surfaceFileLimit(drawing))).rejects.toThrow(/big\.svg: 32\.0 MiB is larger than the 32 MiB limit/);
    await expect(readFile(mesh)).rejects.toThrow(/scan\.ply: .* 32 MiB limit/);
  });
});
