/**
 * The splinekit editor: loads the WebAssembly core, builds the editor and opens the document of
 * the last visit (autosaved locally) or the first sample.
 */
import { init } from '../src/index.js';
import { Editor } from './app/editor.js';
import { installTestHook } from './app/test-hook.js';
import './styles.css';
import { messageOf } from './app/errors.js';

const root = document.getElementById('app');
if (!root) throw new Error('index.html has no #app element');
const editor = new Editor(root);

async function start(): Promise<void> {
  editor.state.setBusy('Loading the splinekit core…');
  try {
    await init();
  } catch (err) {
    editor.state.setError(messageOf(err));
    return;
  } finally {
    editor.state.setBusy(null);
  }
  try {
    const samples = await editor.loadSamples();
    // The document (and mode) of the last visit, autosaved; else the first sample.
    const restored = await editor.restoreSession();
    if (!restored && samples.length > 0) await editor.openSample(samples[0], { undoable: false });
  } catch (err) {
    editor.state.setError(messageOf(err));
  }
  await editor.view.nextFrame();
}

installTestHook(editor, start());
