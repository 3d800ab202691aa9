// The achslint extension: starts `achslint server` and connects VS Code's language client to it.
// Highlighting comes from the TextMate grammar in syntaxes/ and works without the server.
// `npm run build` bundles this file and the language client into dist/extension.js (esbuild), the one
// script the .vsix holds.
"use strict";

const vscode = require("vscode");
const { LanguageClient, State } = require("vscode-languageclient/node");

let client;

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

async function start(context) {
  const watcher = vscode.workspace.createFileSystemWatcher(watchedFiles());
  context.subscriptions.push(watcher);
  client = new LanguageClient(
    "achslint",
    "achslint",
    serverOptions(),
    {
      documentSelector: documentSelector(),
      initializationOptions: initializationOptions(),
      synchronize: { configurationSection: "achslint", fileEvents: watcher },
    },
  );
  try {
    await client.start();
  } catch (error) {
    const how = settings().get("interpreter") ? "achslint.interpreter" : "achslint.path";
    vscode.window.showErrorMessage(
      `achslint: the language server did not start (${error.message || error}). ` +
        `Install it with pip install 'achslint[lsp]' or set ${how}.`,
    );
  }
}

async function stop() {
  if (client && client.state !== State.Stopped) {
    await client.stop();
  }
  client = undefined;
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

module.exports = { activate, deactivate, serverOptions, documentSelector, watchedFiles, initializationOptions };
