// The studio page, built into dist/ by tools/setup.sh (`npm run build`);
// `tendril studio` serves dist/. Relative asset paths: the page also works
// from the file the static view writes.
import { defineConfig } from 'vite';

export default defineConfig({
  base: './',
  build: { outDir: 'dist', emptyOutDir: true, chunkSizeWarningLimit: 2000 },  // first: dist/view comes after
  logLevel: 'warn',
});
