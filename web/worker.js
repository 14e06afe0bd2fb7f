// A worker of the app (`import` or `exercise`, its name): it runs the page's own module,
// the same cached file, so the engine is downloaded once, then its part of the code as a
// chunk (docs/loading.md). It says "ready" once it listens (src/workers.rs).
import init, { worker_main } from './plc-web.js';

await init();
worker_main(self.name);
