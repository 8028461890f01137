import { Emitter } from './events.js';

/**
 * One undoable change. `do()` applies it (also on redo), `undo()` reverts it exactly; both must be
 * deterministic, so a command captures everything it needs (the document it acts on, old values)
 * when it is created.
 */
export interface Command {
  /** Shown in the undo/redo buttons' tooltips, e.g. "Set continuity to G1". */
  readonly label: string;
  do(): void;
  undo(): void;
}

/** The undo/redo stack. Executing a command clears what could be redone. */
export class History {
  readonly events = new Emitter<{ change: History }>();
  private done: Command[] = [];
  private undone: Command[] = [];

  constructor(private readonly limit = 200) {}

  get canUndo(): boolean {
    return this.done.length > 0;
  }
  get canRedo(): boolean {
    return this.undone.length > 0;
  }
  /** Label of the command undo would revert, or null. */
  get undoLabel(): string | null {
    return this.done.at(-1)?.label ?? null;
  }
  get redoLabel(): string | null {
    return this.undone.at(-1)?.label ?? null;
  }

  /** Applies the command and records it. */
  execute(command: Command): void {
    command.do();
    this.done.push(command);
    if (this.done.length > this.limit) this.done.shift();
    this.undone = [];
    this.events.emit('change', this);
  }

  undo(): boolean {
    const command = this.done.pop();
    if (!command) return false;
    command.undo();
    this.undone.push(command);
    this.events.emit('change', this);
    return true;
  }

  redo(): boolean {
    const command = this.undone.pop();
    if (!command) return false;
    command.do();
    this.done.push(command);
    this.events.emit('change', this);
    return true;
  }

  clear(): void {
    this.done = [];
    this.undone = [];
    this.events.emit('change', this);
  }
}
