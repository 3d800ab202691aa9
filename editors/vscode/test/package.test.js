// What the .vsix holds, as the packaging tool lists it (`vsce ls`, the files `npm run package` puts in): the
// one bundled script, the manifest, grammar, language configuration, README and LICENSE; no node_modules.
"use strict";

const assert = require("node:assert/strict");
const { execFileSync } = require("node:child_process");
const path = require("node:path");
const { test } = require("node:test");

const FOLDER = path.join(__dirname, "..");
const PACKAGE = require(path.join(FOLDER, "package.json"));

function packagedFiles() {
  const vsce = path.join(path.dirname(require.resolve("@vscode/vsce/package.json")), "vsce");
  const listed = execFileSync(process.execPath, [vsce, "ls"], { cwd: FOLDER, encoding: "utf8" });
  return listed.split(/\r?\n/).filter((line) => line.trim()).map((line) => line.trim().replace(/\\/g, "/"));
}

test("the .vsix holds one script, the bundle, and nothing from node_modules", () => {
  const files = packagedFiles();
  assert.deepEqual(files.filter((file) => file.endsWith(".js")), [path.posix.normalize(PACKAGE.main)]);
  assert.deepEqual(files.filter((file) => file.split("/").includes("node_modules")), []);
  assert.deepEqual(files.slice().sort(), [
    "LICENSE",
    "README.md",
    "dist/extension.js",
    "language-configuration.json",
    "package.json",
    "syntaxes/achsmds.tmLanguage.json",
  ]);
  assert.deepEqual(PACKAGE.dependencies ?? {}, {}, "bundled: the language client is a build-time dependency");
});
