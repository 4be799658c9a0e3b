// The static view's page as one script and one style sheet (dist/view/),
// which `tendril view` inlines into a single self-contained HTML file.
import { defineConfig } from 'vite';

export default defineConfig({
  base: './',
  build: {
    outDir: 'dist/view', emptyOutDir: true, chunkSizeWarningLimit: 2000, modulePreload: false,
    rollupOptions: { input: 'view.html' },
  },
  logLevel: 'warn',
});
