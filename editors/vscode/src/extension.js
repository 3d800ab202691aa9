// The achslint extension: starts `achslint server` and connects VS Code's language client to it.
// Highlighting comes from the TextMate grammar in syntaxes/ and works without the server.
// `npm run build` bundles this file and the language client into dist/extension.js (esbuild), the one
// script the .vsix holds.
"use strict";

const vscode = require("vscode");
const { CloseAction, ErrorAction, LanguageClient, State } = require("vscode-languageclient/node");

let client;
let watcher; // the running client's file watcher, disposed with it

function settings() {
  return vscode.workspace.getConfiguration("achslint");
}

// How to start the server: `<interpreter> -m achslint server`, else `<path> server`.
function serverOptions() {
  const config = settings();
  const interpreter = (config.get("interpreter") || "").trim();
  if (interpreter) {
    return { command: interpreter, args: ["-m", "achslint", "server"] };
  }
  return { command: (config.get("path") || "achslint").trim(), args: ["server"] };
}

// What the server reads as its settings (the same keys as the `achslint` section).
function initializationOptions() {
  const config = settings();
  return {
    select: config.get("select"),
    extendSelect: config.get("extendSelect"),
    ignore: config.get("ignore"),
    inlayHints: config.get("inlayHints"),
    debounceMs: config.get("debounceMs"),
  };
}

// The file name endings of TwinCAT exports and ISG XML lists (achslint's XML_SUFFIXES): the server finds the
// lists inside by content and says nothing about an XML file without one.
const XML_SUFFIXES = ["xml", "xti", "tsproj"];
const XML_FILES = `**/*.{${XML_SUFFIXES.join(",")}}`;

function documentSelector() {
  const selector = [{ language: "achsmds" }];
  if (settings().get("xml")) {
    selector.push({ scheme: "file", pattern: XML_FILES });
  }
  return selector;
}

// The files whose changes the server hears of: the lists and exports of a machine, the configuration files.
function watchedFiles() {
  const names = ["*.lis", "*.LIS", ".achslint.toml", "achslint.toml", "pyproject.toml"];
  if (settings().get("xml")) {
    names.push(...XML_SUFFIXES.map((suffix) => `*.${suffix}`));
  }
  return `**/{${names.join(",")}}`;
}

// Files matching `achslint.filePatterns` become CNC parameter lists too (every *.lis already is).
function adopt(document) {
  if (document.languageId === "achsmds") {
    return;
  }
  const patterns = settings().get("filePatterns") || [];
  if (patterns.some((pattern) => vscode.languages.match({ pattern }, document) > 0)) {
    vscode.languages.setTextDocumentLanguage(document, "achsmds");
  }
}

// What the client does when the server ends or its connection fails. A server that never got going
// (`achslint` missing, installed without its lsp extra, a wrong interpreter) ends the same way each time:
// it is not started again, and the start's failure says so once. One that ran is started again up to
// RESTARTS times within RESTART_WINDOW_MS, then left stopped with a message saying how to start it.
const RESTARTS = 4;
const RESTART_WINDOW_MS = 3 * 60 * 1000;

function errorHandler(ran, now = Date.now) {
  const ends = [];
  return {
    error: (_error, _message, count) => ({
      action: count !== undefined && count <= 3 ? ErrorAction.Continue : ErrorAction.Shutdown,
    }),
    closed: () => {
      if (!ran()) {
        return { action: CloseAction.DoNotRestart, handled: true };
      }
      const time = now();
      ends.push(time);
      while (ends.length && time - ends[0] > RESTART_WINDOW_MS) {
        ends.shift();
      }
      if (ends.length > RESTARTS) {
        return {
          action: CloseAction.DoNotRestart,
          message:
            `achslint: the language server stopped ${ends.length} times within 3 minutes and is not started ` +
            `again (its output: the "achslint" output channel). Run "achslint: Restart the language server" ` +
            `once it is fixed.`,
        };
      }
      return { action: CloseAction.Restart };
    },
  };
}

async function start(context) {
  watcher = vscode.workspace.createFileSystemWatcher(watchedFiles());
  context.subscriptions.push(watcher);
  let ran = false;
  const started = new LanguageClient(
    "achslint",
    "achslint",
    serverOptions(),
    {
      documentSelector: documentSelector(),
      initializationOptions: initializationOptions(),
      synchronize: { configurationSection: "achslint", fileEvents: watcher },
      errorHandler: errorHandler(() => ran),
      // a failed start is told once, below, with what to do (not also as the bare error of `initialize`)
      initializationFailedHandler: () => false,
    },
  );
  client = started;
  try {
    await started.start();
    ran = true;
  } catch (error) {
    const how = settings().get("interpreter") ? "achslint.interpreter" : "achslint.path";
    // not awaited: the notification stays until it is closed, and activation must not wait for that
    vscode.window
      .showErrorMessage(
        `achslint: the language server did not start (${error.message || error}). ` +
          `Install it with pip install 'achslint[lsp]' or set ${how}; the "achslint" output channel ` +
          `shows what the server said.`,
        "Show output",
      )
      .then((choice) => choice && started.outputChannel.show(true));
  }
}

// Stop a language client: one still starting is waited for (the language client refuses to stop it), one
// whose start failed has nothing to stop.
async function stopClient(given) {
  if (given && given.state === State.Starting) {
    await given.start().catch(() => undefined);
  }
  if (given && given.state === State.Running) {
    await given.stop();
  }
}

async function stop() {
  const stopping = client;
  client = undefined;
  await stopClient(stopping);
  if (watcher) {
    watcher.dispose();
    watcher = undefined;
  }
}

async function activate(context) {
  context.subscriptions.push(
    vscode.commands.registerCommand("achslint.restart", async () => {
      await stop();
      await start(context);
    }),
    vscode.workspace.onDidOpenTextDocument(adopt),
    vscode.workspace.onDidChangeConfiguration(async (event) => {
      if (["achslint.path", "achslint.interpreter", "achslint.xml"].some((key) => event.affectsConfiguration(key))) {
        await stop();
        await start(context);
      }
    }),
  );
  vscode.workspace.textDocuments.forEach(adopt);
  await start(context);
}

function deactivate() {
  return stop();
}

module.exports = {
  activate,
  deactivate,
  serverOptions,
  documentSelector,
  watchedFiles,
  initializationOptions,
  errorHandler,
  stopClient,
  CloseAction,
  ErrorAction,
  State,
};
