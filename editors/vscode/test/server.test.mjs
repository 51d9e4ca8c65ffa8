// kse lsp as an editor sees it: a real LSP client (vscode-languageserver-protocol, the library
// under vscode-languageclient) starts `kse lsp` and works on a formula file and on statecharts.
// KSE_COMMAND names the kse command (default: the repository's ./kse).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import protocol from 'vscode-languageserver-protocol/node.js';

const {
  createProtocolConnection, StreamMessageReader, StreamMessageWriter, InitializeRequest, InitializedNotification,
  DidOpenTextDocumentNotification, DidChangeTextDocumentNotification, PublishDiagnosticsNotification, CompletionRequest,
  DefinitionRequest, HoverRequest, DocumentSymbolRequest, ShutdownRequest, ExitNotification, DiagnosticSeverity,
} = protocol;

const repository = resolve(dirname(fileURLToPath(import.meta.url)), '../../..');
const kse = process.env.KSE_COMMAND || join(repository, 'kse');
const folder = mkdtempSync(join(tmpdir(), 'kse-lsp-'));

let server;
let connection;
let stderr = '';
const waiting = new Map();

/** The diagnostics the server publishes for a document's version. */
function diagnosticsOf(uri, version) {
  return new Promise((done) => waiting.set(`${uri}@${version}`, done));
}

function open(file, languageId, text) {
  const uri = pathToFileURL(file).href;
  writeFileSync(file, text);
  const published = diagnosticsOf(uri, 1);
  connection.sendNotification(DidOpenTextDocumentNotification.type, { textDocument: { uri, languageId, version: 1, text } });
  return { uri, published };
}

function change(uri, version, text) {
  const published = diagnosticsOf(uri, version);
  connection.sendNotification(DidChangeTextDocumentNotification.type, { textDocument: { uri, version }, contentChanges: [{ text }] });
  return published;
}

/** The position of the first `needle` in `text` (plus `shift` characters), 0-based as LSP counts. */
function positionOf(text, needle, shift = 0) {
  const index = text.indexOf(needle);
  assert.ok(index >= 0, `test text lacks ${needle}`);
  const before = text.slice(0, index + shift);
  const line = before.split('\n').length - 1;
  return { line, character: before.length - before.lastIndexOf('\n') - 1 };
}

async function complete(uri, position) {
  const result = await connection.sendRequest(CompletionRequest.type, { textDocument: { uri }, position });
  return Array.isArray(result) ? result : result.items;
}

before(async () => {
  server = spawn(kse, ['lsp'], { stdio: ['pipe', 'pipe', 'pipe'] });
  server.stderr.on('data', (chunk) => { stderr += chunk; });
  connection = createProtocolConnection(new StreamMessageReader(server.stdout), new StreamMessageWriter(server.stdin));
  connection.onNotification(PublishDiagnosticsNotification.type, (params) => {
    const key = `${params.uri}@${params.version}`;
    waiting.get(key)?.(params.diagnostics);
    waiting.delete(key);
  });
  connection.listen();
  const result = await connection.sendRequest(InitializeRequest.type, {
    processId: process.pid, rootUri: pathToFileURL(folder).href, capabilities: {}, workspaceFolders: null,
  });
  assert.equal(result.serverInfo.name, 'kse');
  assert.ok(result.capabilities.completionProvider && result.capabilities.hoverProvider && result.capabilities.definitionProvider
    && result.capabilities.documentSymbolProvider, JSON.stringify(result.capabilities));
  connection.sendNotification(InitializedNotification.type, {});
});

after(async () => {
  if (connection) {
    await connection.sendRequest(ShutdownRequest.type);
    const exited = new Promise((done) => server.on('exit', (code) => done(code)));
    connection.sendNotification(ExitNotification.type);
    assert.equal(await exited, 0, `kse lsp did not exit cleanly; its standard error:\n${stderr}`);
    connection.dispose();
    // a request that failed inside the server is logged there: none may have
    assert.equal(stderr, '', 'kse lsp wrote to its standard error');
  }
});

const FORMULAS = [
  'goalie = (playing | nonPlaying)+',
  'playing = Scan . Kick | Stare',
  'nonPlaying = Wait',
  '',
].join('\n');

test('a formula file: the error at its line and column, completion, definition, hover, symbols', async () => {
  const { uri, published } = open(join(folder, 'Goalie.liveness'), 'liveness', FORMULAS);
  const diagnostics = await published;
  assert.equal(diagnostics.length, 1, JSON.stringify(diagnostics));
  const [mixed] = diagnostics;
  assert.equal(mixed.severity, DiagnosticSeverity.Error);
  // line 2, column 23: the '|' after 'Scan . Kick' mixes choice into a sequence
  assert.deepEqual(mixed.range.start, { line: 1, character: 22 });
  assert.match(mixed.message, /\|/);

  // a capability is completed while its name is typed
  const typing = 'goalie = (playing | nonP\nplaying = Scan . Kick\nnonPlaying = Wait\n';
  await change(uri, 2, typing);
  const items = await complete(uri, { line: 0, character: 24 });
  const nonPlaying = items.find((item) => item.label === 'nonPlaying');
  assert.ok(nonPlaying, `no nonPlaying among ${items.map((item) => item.label)}`);
  assert.equal(nonPlaying.detail, 'capability');
  assert.deepEqual(nonPlaying.textEdit.range, { start: { line: 0, character: 20 }, end: { line: 0, character: 24 } });
  // after a complete name, the grammar's operators
  const operators = (await complete(uri, { line: 1, character: 21 })).map((item) => item.label);
  for (const operator of ['.', '|', '||', '*', '+', '~']) {
    assert.ok(operators.includes(operator), `no ${operator} among ${operators}`);
  }

  const fixed = await change(uri, 3, FORMULAS.replace('Scan . Kick | Stare', '(Scan . Kick) | Stare'));
  assert.deepEqual(await fixed, []);
  // go to definition: from 'nonPlaying' in the root's formula to its own formula on line 3
  const locations = await connection.sendRequest(DefinitionRequest.type, { textDocument: { uri }, position: { line: 0, character: 22 } });
  assert.equal(locations.length, 1);
  assert.equal(locations[0].uri, uri);
  assert.deepEqual(locations[0].range, { start: { line: 2, character: 0 }, end: { line: 2, character: 10 } });

  const onCapability = await connection.sendRequest(HoverRequest.type, { textDocument: { uri }, position: { line: 0, character: 12 } });
  assert.match(onCapability.contents.value, /capability \*\*playing\*\*, line 2/);
  assert.match(onCapability.contents.value, /playing = \(Scan \. Kick\) \| Stare/);
  const onActivity = await connection.sendRequest(HoverRequest.type, { textDocument: { uri }, position: { line: 1, character: 12 } });
  assert.match(onActivity.contents.value, /activity \*\*Scan\*\*/);

  const symbols = await connection.sendRequest(DocumentSymbolRequest.type, { textDocument: { uri } });
  assert.deepEqual(symbols.map((symbol) => symbol.name), ['goalie', 'playing', 'nonPlaying']);
  assert.deepEqual(symbols[1].selectionRange, { start: { line: 1, character: 0 }, end: { line: 1, character: 7 } });
});

test('the original tool\'s .txt formula file: its problems too', async () => {
  const { published } = open(join(folder, 'Goalie.txt'), 'plaintext', 'Goalie\ngoalie = (playing\n');
  const diagnostics = await published;
  // as kse transform says it: G.txt:2:18: error: unbalanced '(' at column 10 ...
  const unbalanced = diagnostics.find((diagnostic) => diagnostic.severity === DiagnosticSeverity.Error);
  assert.deepEqual(unbalanced.range.start, { line: 1, character: 17 });
  assert.match(unbalanced.message, /unbalanced '\(' at column 10/);
  // and the warning that 'playing', defined nowhere and not capitalised, becomes an activity
  const warning = diagnostics.find((diagnostic) => diagnostic.severity === DiagnosticSeverity.Warning);
  assert.deepEqual(warning.range.start, { line: 1, character: 10 });
  assert.match(warning.message, /'playing' is not defined/);
});

test('a statechart: a bad expression reported at its line and column in the file, through XML entities', async () => {
  const goalie = readFileSync(join(repository, 'examples/Goalie/Goalie.stct'), 'utf8');
  // a misspelt topic after '&amp;&amp;&#xA; !ballAway(': each entity is one character of the expression
  const misspelt = '!ballAway(worldstat.Data.WorldInfo) &amp;&amp; !readyToKick';
  const broken = goalie
    .replace('!ballAway(worldstate.Data.WorldInfo) &amp;&amp; !readyToKick', misspelt)
    .replace('player_state()==PLAYER_PLAYING]" name="0.2.2.2_TO_playing"', 'player_state()==PLAYER_PLAYING &amp;&amp; ]" name="0.2.2.2_TO_playing"');
  assert.notEqual(broken, goalie);
  const { published } = open(join(folder, 'Goalie.stct'), 'kse-statechart', broken);
  const diagnostics = await published;
  assert.equal(diagnostics.length, 2, JSON.stringify(diagnostics, null, 1));
  const [syntax, topic] = diagnostics.sort((a, b) => a.range.start.line - b.range.start.line);
  assert.equal(syntax.severity, DiagnosticSeverity.Error);
  assert.deepEqual(syntax.range.start, positionOf(broken, '&amp;&amp; ]" name="0.2.2.2_TO_playing"', '&amp;&amp; '.length));
  assert.match(syntax.message, /^transition 0\.2\.2\.2_TO_playing: /);
  assert.deepEqual(topic.range.start, positionOf(broken, misspelt, '!ballAway('.length));
  assert.deepEqual(topic.range.end, positionOf(broken, misspelt, '!ballAway(worldstat'.length));
  assert.match(topic.message, /worldstat/);
  // the example itself is clean
  assert.deepEqual(await change(pathToFileURL(join(folder, 'Goalie.stct')).href, 2, goalie), []);
});

test('a statechart: completion inside a TE attribute proposes topics, message types, fields and escaped operators', async () => {
  const text = [
    '<?xml version="1.0" encoding="ASCII"?>',
    '<statechart:Model xmi:version="2.0" xmlns:xmi="http://www.omg.org/XMI" xmlns:statechart="http://statechart/1.0" name="T">',
    '  <transitions TE="[behavior.State.HeadToBMessage.ballfound()&gt;0 &amp;&amp; worldstate.State." name="a_TO_b"/>',
    '  <transitions TE="[wor" name="b_TO_c"/>',
    '  <transitions TE="[worldstate.State.GameStateMessage." name="c_TO_d"/>',
    '  <transitions TE="[TimeoutCheck(behavior)" name="d_TO_e"/>',
    '</statechart:Model>',
    '',
  ].join('\n');
  const { uri, published } = open(join(folder, 'Typing.stct'), 'kse-statechart', text);
  await published;

  const types = await complete(uri, positionOf(text, 'worldstate.State." name="a_TO_b"', 'worldstate.State.'.length));
  const gameState = types.find((item) => item.label === 'GameStateMessage');
  assert.ok(gameState, `no GameStateMessage among ${types.map((item) => item.label)}`);
  assert.equal(gameState.detail, 'message type');

  const topics = await complete(uri, positionOf(text, '[wor"', 4));
  const worldstate = topics.find((item) => item.label === 'worldstate');
  assert.ok(worldstate, `no worldstate among ${topics.map((item) => item.label)}`);
  assert.deepEqual(worldstate.textEdit.range, { start: positionOf(text, '[wor"', 1), end: positionOf(text, '[wor"', 4) });

  const fields = (await complete(uri, positionOf(text, 'GameStateMessage." name', 'GameStateMessage.'.length))).map((item) => item.label);
  assert.ok(fields.includes('player_state'), `no player_state among ${fields}`);

  const operators = await complete(uri, positionOf(text, 'TimeoutCheck(behavior)"', 'TimeoutCheck(behavior)'.length));
  const and = operators.find((item) => item.label === '&&');
  assert.ok(and, `no && among ${operators.map((item) => item.label)}`);
  assert.equal(and.textEdit.newText, '&amp;&amp;');

  const hover = await connection.sendRequest(HoverRequest.type, { textDocument: { uri }, position: positionOf(text, 'GameStateMessage." name', 3) });
  assert.match(hover.contents.value, /message \*\*.*GameStateMessage\*\*/);
  assert.match(hover.contents.value, /player_state\(\)/);

  const symbols = await connection.sendRequest(DocumentSymbolRequest.type, { textDocument: { uri } });
  assert.deepEqual(symbols.map((symbol) => symbol.name), ['a_TO_b', 'b_TO_c', 'c_TO_d', 'd_TO_e']);
});
