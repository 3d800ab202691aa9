// The bundled extension (dist/extension.js, built by `npm run build` before the tests): it loads with nothing
// but VS Code's API and Node's own modules, and hands the language client the files and settings
// package.json promises. VS Code's API is a stand-in here that answers with package.json's defaults.
"use strict";

const assert = require("node:assert/strict");
const Module = require("node:module");
const path = require("node:path");
const { test } = require("node:test");

const HERE = __dirname;
const BUNDLE = path.join(HERE, "..", "dist", "extension.js");
const PACKAGE = require(path.join(HERE, "..", "package.json"));
const PROPERTIES = PACKAGE.contributes.configuration.properties;

// Any other part of VS Code's API the language client touches while it loads (it extends some of its
// classes): a class whose every property is such a class again.
function anything() {
  return new Proxy(class {}, {
    get: (target, key) => (key in target ? target[key] : anything()),
  });
}

// Settings as VS Code gives them: the package.json defaults, with `changed` on top.
function fakeVscode(changed = {}) {
  const configuration = {
    get: (key) => (key in changed ? changed[key] : PROPERTIES[`achslint.${key}`].default),
  };
  const given = { workspace: { getConfiguration: () => configuration } };
  return new Proxy(given, { get: (target, key) => (key in target ? target[key] : anything()) });
}

// Load the bundle afresh with `vscode` as given; records every other module it asks for.
function loadBundle(vscode) {
  const asked = [];
  const original = Module._load;
  Module._load = function load(request, ...rest) {
    if (request === "vscode") {
      return vscode;
    }
    asked.push(request);
    return original.call(this, request, ...rest);
  };
  try {
    delete require.cache[require.resolve(BUNDLE)];
    return { extension: require(BUNDLE), asked };
  } finally {
    Module._load = original;
  }
}

// A VS Code glob (`**/`, `*`, `{a,b}`) as a regular expression on a path with forward slashes.
function globRegex(glob) {
  let source = "";
  for (let i = 0; i < glob.length; i += 1) {
    const c = glob[i];
    if (glob.startsWith("**/", i)) {
      source += "(?:.*/)?";
      i += 2;
    } else if (c === "*") {
      source += "[^/]*";
    } else if (c === "{") {
      source += "(?:";
    } else if (c === "}") {
      source += ")";
    } else if (c === ",") {
      source += "|";
    } else {
      source += c.replace(/[.+?^$()|[\]\\]/g, "\\$&");
    }
  }
  return new RegExp(`^${source}$`);
}

function selects(selector, file) {
  return selector.some((filter) => filter.pattern !== undefined && globRegex(filter.pattern).test(file));
}

test("the bundle needs nothing from node_modules: only vscode and Node's own modules", () => {
  const { extension, asked } = loadBundle(fakeVscode());
  assert.equal(typeof extension.activate, "function");
  assert.equal(typeof extension.deactivate, "function");
  const outside = asked.filter((name) => name !== BUNDLE && !Module.isBuiltin(name));
  assert.deepEqual(outside, []);
  assert.equal(path.normalize(PACKAGE.main), path.normalize(path.relative(path.join(HERE, ".."), BUNDLE)));
});

test("achslint.xml hands the server TwinCAT exports and ISG XML lists (.xti, .tsproj, .xml)", () => {
  const exports = ["project/Axis_X.xti", "project/machine.tsproj", "listen/ax_mds_1.xml", "Update/achsmds1-Update.xml"];
  const on = loadBundle(fakeVscode()).extension;
  assert.equal(PROPERTIES["achslint.xml"].default, true);
  for (const file of exports) {
    assert.ok(selects(on.documentSelector(), file), file);
    assert.ok(globRegex(on.watchedFiles()).test(file), file);
  }
  assert.ok(!selects(on.documentSelector(), "notes/readme.md"));
  assert.deepEqual(on.documentSelector().filter((f) => f.language), [{ language: "achsmds" }]);
  const off = loadBundle(fakeVscode({ xml: false })).extension;
  for (const file of exports) {
    assert.ok(!selects(off.documentSelector(), file), file);
    assert.ok(!globRegex(off.watchedFiles()).test(file), file);
  }
  for (const file of ["listen/achsmds1.lis", "LISTEN/ACHSMDS1.LIS", "achslint.toml", "sub/pyproject.toml"]) {
    assert.ok(globRegex(off.watchedFiles()).test(file), file);
  }
});

test("the server gets the settings package.json declares, debounceMs 0 unless set", () => {
  const given = loadBundle(fakeVscode()).extension.initializationOptions();
  assert.equal(given.debounceMs, 0);
  assert.deepEqual(Object.keys(given).sort(), ["debounceMs", "extendSelect", "ignore", "inlayHints", "select"]);
  for (const key of Object.keys(given)) {
    assert.ok(`achslint.${key}` in PROPERTIES, key);
  }
  assert.equal(loadBundle(fakeVscode({ debounceMs: 150 })).extension.initializationOptions().debounceMs, 150);
});

// When the server ends: one that never answered `initialize` (achslint not installed, or without its lsp
// extra, a wrong interpreter) is not started again and again (each start ending the same way, with a pop-up
// each), and one that ran is restarted a few times, then left stopped with a message that says what to do.
test("a server that never started is not restarted; one that keeps crashing is restarted a few times", () => {
  const { errorHandler, CloseAction, ErrorAction } = loadBundle(fakeVscode()).extension;
  let ran = false;
  let clock = 0;
  const handler = errorHandler(() => ran, () => clock);
  const early = handler.closed();
  assert.equal(early.action, CloseAction.DoNotRestart);
  assert.equal(early.handled, true, "the start's own failure message says it once");
  ran = true;
  const actions = [];
  for (let i = 0; i < 6; i += 1) {
    clock += 1000;
    actions.push(handler.closed());
  }
  assert.deepEqual(actions.map((a) => a.action), [2, 2, 2, 2, 1, 1].map((n) => (n === 2 ? CloseAction.Restart : CloseAction.DoNotRestart)));
  assert.match(actions[4].message, /achslint: Restart the language server/);
  clock += 10 * 60 * 1000; // long after: a crash now is a new one
  assert.equal(handler.closed().action, CloseAction.Restart);
  assert.equal(handler.error(new Error("x"), undefined, 1).action, ErrorAction.Continue);
  assert.equal(handler.error(new Error("x"), undefined, 5).action, ErrorAction.Shutdown);
});

// A client still starting cannot be stopped (the language client throws): the restart command and a changed
// achslint.path wait for the start to end first, and a client whose start failed is not stopped.
test("stopping a client waits for its start and leaves a failed one alone", async () => {
  const { stopClient, State } = loadBundle(fakeVscode()).extension;
  const calls = [];
  // A client in `state` whose start (when asked while it is starting) ends in `after`; stop() throws unless
  // it runs, as the language client's does.
  function fakeClient(state, after) {
    const client = {
      state,
      start: async () => {
        calls.push("start");
        client.state = after;
        if (after !== State.Running) {
          throw new Error("the server ended before it answered initialize");
        }
      },
      stop: async () => {
        if (client.state !== State.Running) {
          throw new Error(`Client is not running and can't be stopped. It's current state is: ${client.state}`);
        }
        calls.push("stop");
      },
    };
    return client;
  }
  await stopClient(fakeClient(State.Starting, State.Running));
  assert.deepEqual(calls, ["start", "stop"]);
  calls.length = 0;
  await stopClient(fakeClient(State.Starting, State.Stopped)); // the start failed meanwhile
  await stopClient(fakeClient(State.Stopped, State.Stopped));
  assert.deepEqual(calls, ["start"]);
  await stopClient(undefined);
});
