// Run a Python script in Pyodide under Node, with a folder of this computer mounted.
//
//   node run.mjs FOLDER SCRIPT.py
//
// FOLDER is mounted at /src (read and write) and is the script's working directory; the
// script's output goes to this process's output. Exit code 1 when the script raises.
// Only Pyodide's core runs: no package of its distribution (numpy, ...) is loaded.
import { readFileSync } from "node:fs";
import { loadPyodide } from "pyodide";

const [folder, script] = process.argv.slice(2);
if (!folder || !script) {
  console.error("usage: node run.mjs FOLDER SCRIPT.py");
  process.exit(2);
}
const pyodide = await loadPyodide({ stdout: console.log, stderr: console.error });
pyodide.FS.mkdir("/src");
pyodide.FS.mount(pyodide.FS.filesystems.NODEFS, { root: folder }, "/src");
pyodide.FS.chdir("/src");
try {
  await pyodide.runPythonAsync(readFileSync(script, "utf8"));
} catch (error) {
  console.error(String(error));
  process.exit(1);
}
