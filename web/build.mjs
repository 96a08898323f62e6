// Builds the viewer into dist/ (committed, embedded in foveal-server): one script, one stylesheet
// and the page, and the same three for the psychophysics page. Deterministic, so
// `git diff --exit-code dist` tells whether the bundle is stale.
import { build } from "esbuild";
import { copyFileSync, mkdirSync, readFileSync, writeFileSync } from "node:fs";

mkdirSync("dist", { recursive: true });
await build({
  entryPoints: ["src/main.ts"],
  bundle: true,
  minify: true,
  format: "iife",
  target: "es2022",
  legalComments: "none",
  outfile: "dist/viewer.js",
  logLevel: "warning",
});
writeFileSync(
  "dist/viewer.css",
  readFileSync("node_modules/uplot/dist/uPlot.min.css", "utf8") + "\n" + readFileSync("src/viewer.css", "utf8"),
);
copyFileSync("src/index.html", "dist/index.html");
// The psychophysics page (/psych): its own script, stylesheet and page.
await build({
  entryPoints: ["src/psych/main.ts"],
  bundle: true,
  minify: true,
  format: "iife",
  target: "es2022",
  legalComments: "none",
  outfile: "dist/psych.js",
  logLevel: "warning",
});
copyFileSync("src/psych/psych.css", "dist/psych.css");
copyFileSync("src/psych.html", "dist/psych.html");
