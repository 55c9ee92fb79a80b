#!/bin/sh
# A test adapter (docs/adapters.md) in POSIX sh whose words are markup: its
# version, a line on standard error and its answer to the first "advance"
# ("error" and a script) must reach report.md and the pages as text.
if [ "$1" = --version ]; then echo "html_liar <i>1</i>"; exit 0; fi
while read -r key rest; do
  [ "$key" = start ] && break
done
echo '<img src=x onerror=alert(2)>' >&2
echo ready
read -r key rest
echo 'error <script>alert(1)</script>'
