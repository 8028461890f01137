import type { Command } from '../../app/history.js';
import type { Skin3DSession } from './session.js';

/** Opening a cage: shows the new session; undo shows the one before (or none). */
export class OpenCageCommand implements Command {
  readonly label: string;

  constructor(
    private readonly show: (session: Skin3DSession | null) => void,
    private readonly previous: Skin3DSession | null,
    private readonly next: Skin3DSession,
  ) {
    this.label = `Open ${next.file}`;
  }

  do(): void {
    this.show(this.next);
  }

  undo(): void {
    this.show(this.previous);
  }
}
