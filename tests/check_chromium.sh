# check_chromium.sh: sourced by the browser checks (check_html_layout.sh,
# check_html_render.sh). Without chromium the caller is skipped (exit 77).
# chromium_headless WIDTH,HEIGHT ARGS...: headless Chromium, root-safe and
# offline, with a fresh profile under $tmp (the caller's temporary directory)
# and its messages appended to $tmp/chromium.log; chromium_log: their tail.
if ! command -v chromium >/dev/null 2>&1; then
  echo "SKIP: chromium not installed"
  exit 77
fi
chromium_headless() {
  local size=$1 profile
  shift
  profile=$(mktemp -d "$tmp/profile.XXXXXX")
  HOME="$tmp" timeout -k 5 60 chromium --headless --no-sandbox --disable-gpu --disable-quic \
    --no-first-run --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile" --window-size="$size" "$@" 2>>"$tmp/chromium.log"
}
chromium_log() { grep -v dbus "$tmp/chromium.log" | tail -n 5; }
