import { test as base, expect } from '@playwright/test';
import { collectErrors } from './helpers.js';

/**
 * `test` with a page whose console errors and uncaught exceptions fail the test: every test of
 * the editor also checks that the console stays clean.
 */
export const test = base.extend<{ consoleErrors: string[] }>({
  consoleErrors: [
    async ({ page }, use) => {
      const errors = collectErrors(page);
      await use(errors);
      expect(errors, 'console errors and page errors').toEqual([]);
    },
    { auto: true },
  ],
});

export { expect };
