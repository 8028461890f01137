/**
 * Request/response over a dedicated worker, the worker's side (see worker-client.ts for the
 * message shapes): requests are handled one at a time, in the order they came, and a handler that
 * throws answers its request with `{ type: 'error', id, message }`.
 */
import type { WorkerMessage } from './worker-client.js';
import { messageOf } from './errors.js';

/** The error reply every protocol has. */
export interface ErrorReply {
  type: 'error';
  id: number;
  message: string;
}

/** Posts a reply; `transfer` lists buffers handed over instead of copied. */
export type PostReply<Reply> = (reply: Reply, transfer?: Transferable[]) => void;

/** The parts of a dedicated worker's global scope used here (web/ compiles with the DOM lib). */
interface WorkerScope {
  postMessage(message: unknown, options?: { transfer?: Transferable[] }): void;
  addEventListener(type: 'message', listener: (e: MessageEvent) => void): void;
}

/**
 * Serves requests in this worker: `handle` answers one request through `post` (once, or with
 * 'progress' replies before its last one); it may be async. Returns `post` for use outside.
 */
export function serveRequests<Request extends WorkerMessage, Reply extends WorkerMessage>(
  handle: (request: Request, post: PostReply<Reply>) => void | Promise<void>,
): PostReply<Reply> {
  const scope = self as unknown as WorkerScope;
  const post: PostReply<Reply> = (reply, transfer = []) => scope.postMessage(reply, { transfer });
  let queue: Promise<void> = Promise.resolve();
  scope.addEventListener('message', (e: MessageEvent<Request>) => {
    const request = e.data;
    queue = queue.then(async () => {
      try {
        await handle(request, post);
      } catch (err) {
        const reply: ErrorReply = { type: 'error', id: request.id, message: messageOf(err) };
        scope.postMessage(reply);
      }
    });
  });
  return post;
}
