// Chromium driven over the DevTools protocol through --remote-debugging-pipe: the browser reads
// commands on its fd 3 and writes answers and events on its fd 4, each message one JSON text
// followed by a NUL byte. No websocket, no npm package: plain node.
import { spawn } from 'node:child_process';

export function launchChromium(binary, args) {
  // Its own process group, so that kill() ends the renderer and GPU processes with it.
  const child = spawn(binary, [...args, '--remote-debugging-pipe'],
                      { stdio: ['ignore', 'pipe', 'pipe', 'pipe', 'pipe'], detached: true });
  let log = '';
  const keepLog = (chunk) => {
    log += chunk;
    if (log.length > 200000) log = log.slice(-100000);
  };
  child.stdout.on('data', keepLog);
  child.stderr.on('data', keepLog);
  const toBrowser = child.stdio[3];
  const fromBrowser = child.stdio[4];
  let nextId = 1;
  const pending = new Map();  // id -> { resolve, reject, method }
  const listeners = [];
  let exited = null;

  const failAll = (error) => {
    for (const { reject } of pending.values()) reject(error);
    pending.clear();
  };
  let buffered = [];
  fromBrowser.on('data', (chunk) => {
    let start = 0;
    for (let end = chunk.indexOf(0); end !== -1; end = chunk.indexOf(0, start)) {
      buffered.push(chunk.subarray(start, end));
      const text = Buffer.concat(buffered).toString('utf8');
      buffered = [];
      start = end + 1;
      const message = JSON.parse(text);
      if (message.id !== undefined) {
        const call = pending.get(message.id);
        if (!call) continue;
        pending.delete(message.id);
        if (message.error) call.reject(new Error(`${call.method}: ${message.error.message}`));
        else call.resolve(message.result);
      } else {
        for (const listener of listeners) listener(message);
      }
    }
    if (start < chunk.length) buffered.push(chunk.subarray(start));
  });
  // A write after the browser died must not throw out of the test: the pending calls fail instead.
  toBrowser.on('error', () => {});
  fromBrowser.on('error', () => {});
  child.on('error', (error) => {
    exited = `could not start ${binary}: ${error.message}`;
    failAll(new Error(exited));
  });
  child.on('exit', (code, signal) => {
    exited = `chromium exited (${signal || code})`;
    failAll(new Error(exited));
  });

  return {
    process: child,
    log: () => log,
    // Sends one command (to the browser, or to a page when sessionId is given); resolves to its
    // result.
    send(method, params = {}, sessionId = undefined) {
      if (exited) return Promise.reject(new Error(exited));
      const id = nextId++;
      const message = sessionId ? { id, method, params, sessionId } : { id, method, params };
      return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject, method });
        toBrowser.write(JSON.stringify(message) + '\0');
      });
    },
    // Calls listener(message) for every event: { method, params, sessionId }.
    onEvent(listener) {
      listeners.push(listener);
    },
    exited: () => exited !== null,
    kill() {
      try {
        process.kill(-child.pid, 'SIGKILL');
      } catch {
        // already gone
      }
    },
  };
}
