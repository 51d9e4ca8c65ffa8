// Bundles the diagram client into dist/: kse-diagram.js, kse-diagram.css (GLSP's, sprotty's and
// codicons' styles included), the codicon font, and index.html. `node build.mjs --dev` keeps the
// output readable (no minification, inline source maps).
import * as esbuild from 'esbuild';
import { mkdir, readFile, readdir, rm, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const dist = path.join(here, 'dist');
const dev = process.argv.includes('--dev');

await rm(dist, { recursive: true, force: true });
await mkdir(dist, { recursive: true });

const result = await esbuild.build({
    absWorkingDir: here,
    entryPoints: { 'kse-diagram': 'src/main.ts' },
    outdir: dist,
    bundle: true,
    format: 'iife',
    platform: 'browser',
    // Chromium and WebKitGTK (the SWT Browser on Linux) of the last years
    target: ['es2020', 'chrome90', 'safari15'],
    minify: !dev,
    sourcemap: dev ? 'inline' : false,
    legalComments: dev ? 'inline' : 'linked',
    charset: 'utf8',
    tsconfig: 'tsconfig.json',
    loader: { '.ttf': 'file', '.woff': 'file', '.woff2': 'file', '.svg': 'file', '.png': 'file' },
    assetNames: '[name]',
    define: { 'process.env.NODE_ENV': dev ? '"development"' : '"production"' },
    metafile: true,
    logLevel: 'warning'
});

const outputs = Object.keys(result.metafile.outputs).map(file => path.relative(dist, path.resolve(here, file)));
const script = outputs.find(file => file.endsWith('.js'));
const style = outputs.find(file => file.endsWith('.css'));
if (!script || !style) {
    throw new Error(`esbuild produced no script or no style sheet: ${outputs.join(', ')}`);
}

const template = await readFile(path.join(here, 'src', 'index.html'), 'utf8');
await writeFile(path.join(dist, 'index.html'), template.replace('%CSS%', style).replace('%JS%', script));

const files = (await readdir(dist)).sort();
console.log(`dist/: ${files.join(', ')}`);
