// The TextMate grammar, tokenized as VS Code does (vscode-textmate + the Oniguruma WebAssembly build).
"use strict";

const assert = require("node:assert/strict");
const fs = require("node:fs");
const path = require("node:path");
const { test } = require("node:test");
const oniguruma = require("vscode-oniguruma");
const textmate = require("vscode-textmate");

const HERE = __dirname;
const GRAMMAR = path.join(HERE, "..", "syntaxes", "achsmds.tmLanguage.json");
// Copies of the repository's example lists (fixtures/<same path>; tests/test_vscode_extension.py keeps them
// equal), so that this folder tests on its own.
const EXAMPLES = path.join(HERE, "fixtures", "examples");

async function loadGrammar() {
  const wasm = fs.readFileSync(require.resolve("vscode-oniguruma/release/onig.wasm"));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new textmate.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (text) => new oniguruma.OnigString(text),
    }),
    loadGrammar: async (scopeName) =>
      scopeName === "source.achsmds"
        ? textmate.parseRawGrammar(fs.readFileSync(GRAMMAR, "utf8"), GRAMMAR)
        : null,
  });
  return registry.loadGrammar("source.achsmds");
}

const grammarPromise = loadGrammar();

// Every line of a text as [{text, scopes}] tokens; lines end at CR, LF or CRLF, as in the editor.
async function tokenize(text) {
  const grammar = await grammarPromise;
  let stack = textmate.INITIAL;
  return text.split(/\r\n|\r|\n/).map((line) => {
    const result = grammar.tokenizeLine(line, stack);
    stack = result.ruleStack;
    return result.tokens.map((token) => ({
      text: line.slice(token.startIndex, token.endIndex),
      scopes: token.scopes,
    }));
  });
}

test("every comment form, strings, hex, references and Ende get their scopes", async () => {
  const text = fs.readFileSync(path.join(HERE, "fixtures", "forms.lis"), "latin1");
  const expected = JSON.parse(fs.readFileSync(path.join(HERE, "fixtures", "forms.expected.json"), "utf8"));
  const lines = await tokenize(text);
  for (const [line, tokenText, scope] of expected) {
    const tokens = lines[line - 1];
    const found = tokens.find((token) => token.text === tokenText && token.scopes.includes(scope));
    assert.ok(found, `line ${line}: no token ${JSON.stringify(tokenText)} with ${scope}; got ` +
      JSON.stringify(tokens.map((t) => [t.text, t.scopes.slice(1)])));
  }
});

test("a string followed by # is not a comment, a number followed by # is", async () => {
  const [afterString, afterNumber] = await tokenize('kopf.log_achs_name "X" # note\nkopf.achs_nr 1 # note');
  const stringHash = afterString.find((t) => t.text === "# note");
  const numberHash = afterNumber.find((t) => t.text === "# note");
  assert.ok(stringHash.scopes.some((s) => s.startsWith("invalid.illegal")));
  assert.ok(!stringHash.scopes.some((s) => s.startsWith("comment")));
  assert.ok(numberHash.scopes.includes("comment.line.number-sign.achsmds"));
});

test("End and ENDE are not the end marker", async () => {
  const lines = await tokenize("End\nENDE\nEnde");
  assert.ok(!lines[0].some((t) => t.scopes.includes("keyword.control.end.achsmds")));
  assert.ok(!lines[1].some((t) => t.scopes.includes("keyword.control.end.achsmds")));
  assert.ok(lines[2].some((t) => t.text === "Ende" && t.scopes.includes("keyword.control.end.achsmds")));
});

test("OR-combined flags of start-up and channel lists are symbols, not text after a value", async () => {
  const lines = await tokenize(
    "error_protocol_mode   REPORT | REPORT_EXTENDED |PRINT   ( P-STUP-00167\n" +
      "configuration.channel[0].path_preparation.function  FCT_DEFAULT | FCT_M_PRE_OUTPUT\n" +
      "error_protocol_mode  REPORT |\n",
  );
  for (const tokens of lines.slice(0, 2)) {
    assert.ok(!tokens.some((t) => t.scopes.some((s) => s.startsWith("invalid"))),
      JSON.stringify(tokens.map((t) => [t.text, t.scopes.slice(1)])));
    assert.ok(tokens.some((t) => t.text === "|" && t.scopes.includes("keyword.operator.bitwise.or.achsmds")));
  }
  const flags = lines[0].filter((t) => t.scopes.includes("constant.language.symbol.achsmds") && /\w/.test(t.text));
  assert.deepEqual(flags.map((t) => t.text.trim()), ["REPORT", "REPORT_EXTENDED", "PRINT"]);
  assert.ok(lines[0].some((t) => t.text.startsWith("( P-STUP") && t.scopes.includes("comment.line.parenthesis.achsmds")));
  // a bar with no flag after it names no symbol (LIS203): painted as stray text
  assert.ok(lines[2].some((t) => t.text.trim() === "|" && t.scopes.some((s) => s.startsWith("invalid"))));
});

// Lists of every kind the repository keeps as clean examples (axis, channel, start-up, tool data ... lists;
// the SDK's start-up list with its OR-combined flags).
function exampleLists(folder = EXAMPLES) {
  return fs.readdirSync(folder, { withFileTypes: true }).flatMap((entry) => {
    const full = path.join(folder, entry.name);
    if (entry.isDirectory()) {
      return exampleLists(full);
    }
    return entry.name.endsWith(".lis") ? [path.relative(EXAMPLES, full)] : [];
  });
}

test("the repository's example lists of every kind tokenize without any invalid token", async () => {
  const files = exampleLists();
  assert.ok(files.length >= 20);
  for (const name of files) {
    const lines = await tokenize(fs.readFileSync(path.join(EXAMPLES, name), "latin1"));
    lines.forEach((tokens, index) => {
      for (const token of tokens) {
        assert.ok(!token.scopes.some((s) => s.startsWith("invalid")),
          `${name}:${index + 1}: ${JSON.stringify(token.text)} is ${token.scopes.join(" ")}`);
      }
      const words = tokens.filter((t) => t.text.trim() && t.scopes.length === 1);
      assert.deepEqual(words, [], `${name}:${index + 1}: text without a scope`);
    });
  }
});
