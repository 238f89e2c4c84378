#!/usr/bin/env bash
# Usage: run_browser_tests.sh ACANTHUS
# Runs browser.test.js in headless Chromium. puppeteer-core comes from package-lock.json
# (npm ci, once); the browser is the system's (Debian `chromium`, from scripts/install-deps).
# Exit 77 (ctest: skipped) only when no browser is installed and none can be.
set -uo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
browser="${ACANTHUS_CHROMIUM:-}"
for candidate in chromium chromium-browser google-chrome; do
  [ -n "$browser" ] && break
  browser="$(command -v "$candidate" 2>/dev/null || true)"
done
if [ -z "$browser" ]; then
  echo "SKIPPED: no Chromium found (install the Debian package 'chromium': scripts/install-deps)"
  exit 77
fi
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "FAIL: node and npm are needed (Debian packages 'nodejs' and 'npm': scripts/install-deps)"
  exit 1
fi
if [ ! -d "$HERE/node_modules/puppeteer-core" ]; then
  echo "installing puppeteer-core from package-lock.json (npm ci)"
  (cd "$HERE" && npm ci --no-audit --no-fund) || { echo "FAIL: npm ci failed"; exit 1; }
fi
exec node "$HERE/browser.test.js" "$1" "$browser"
