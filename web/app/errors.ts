/** The message of an error, or of anything else thrown, for the status bar and worker replies. */
export function messageOf(err: unknown): string {
  return err instanceof Error ? err.message : String(err);
}
