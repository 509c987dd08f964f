#!/bin/sh
# Rebuilds dist/viewer.js from src/viewer.js and three.js (npm), as one minified script with
# three.js's MIT licence kept. The result is checked in; run this after changing src/.
set -eu
cd "$(dirname "$0")"
npm ci --no-audit --no-fund --loglevel=error
npx esbuild src/viewer.js --bundle --minify --format=iife --target=es2020 \
  --legal-comments=inline --outfile=dist/viewer.js \
  --banner:js="/* locus viewer: src/viewer.js (MIT OR Apache-2.0) bundled with three.js $(node -p 'require("./node_modules/three/package.json").version') (MIT, see THREE-LICENSE) */"
