#!/usr/bin/env python3
"""The CTest case doc_heat_diffusion_in_browser: opens every page of the built manual
(user manual and reference) in headless Chromium, as a reader without network access
would, and checks what the reader sees:
  - no formula is left as raw TeX (\\( or \\[ in the visible text) and MathJax reports
    no TeX error (an undefined macro is shown in red, not typeset);
  - every image loads (no broken image), and no file the page needs is missing;
  - nothing is loaded from the network (such requests are refused, as offline), nor
    from outside the manual's folder (it must work once installed or copied);
  - no JavaScript error (uncaught exception or console error).
It keeps a screenshot of the first page (index.html, the user manual) in the output
folder, first_page.png, for a person to look at.

Chromium is driven through the DevTools protocol over a pipe (--remote-debugging-pipe):
Python's standard library only, and no TCP port that parallel runs could compete for.

Usage: check_doc_in_browser.py HTML_DIR OUTPUT_DIR [--browser PATH] [--page NAME...]
Exit status: 0 all pages pass, 1 a check failed, 77 no Chromium (CTest: skipped).
"""
import argparse
import base64
import fcntl
import json
import os
import select
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.parse

SKIP = 77
BROWSER_NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
# What a reader's window shows; the screenshots have this size.
VIEWPORT = (1280, 1024)
# Generous: a loaded 2-core CI machine also runs compilers while this test runs.
LOAD_TIMEOUT = 60.0
TYPESET_TIMEOUT = 60.0

# Runs in the page after its load event: waits until MathJax has typeset the page
# (its startup hook "End", then an empty turn of its queue), then returns what the
# reader would see as wrong. MathJax keeps the TeX of typeset formulas in
# <script type="math/tex"> elements, which innerText does not show.
CHECK_PAGE_JS = r"""
(async () => {
  const timeout = %(timeout)d;
  let mathjax = 'not loaded';
  if (window.MathJax && window.MathJax.Hub && window.MathJax.Hub.Register) {
    mathjax = await new Promise(resolve => {
      const timer = setTimeout(() => resolve('still typesetting after ' + timeout / 1000 + ' s'), timeout);
      // Braces: the hook must not return Queue's callback, which MathJax would wait for
      // (a deadlock once startup is over).
      MathJax.Hub.Register.StartupHook('End', () => {
        MathJax.Hub.Queue(() => { clearTimeout(timer); resolve('done'); });
      });
    });
  }
  const text = document.body.innerText;
  const raw = [];
  const re = /\\[(\[]|\\begin\{|\[Math Processing Error\]/g;
  let m;
  while ((m = re.exec(text)) !== null && raw.length < 5) {
    raw.push(text.slice(Math.max(0, m.index - 30), m.index + 50).replace(/\s+/g, ' '));
  }
  // The TeX input marks the formulas it could not parse (whatever the output draws).
  const texErrors = mathjax === 'not loaded' ? [] :
    MathJax.Hub.getAllJax().filter(jax => jax.texError).slice(0, 5).map(jax => {
      const shown = document.getElementById(jax.inputID + '-Frame');
      return jax.originalText.trim() + ' -> ' + (shown ? shown.textContent : '?');
    });
  const brokenImages = Array.from(document.images)
                            .filter(i => !(i.complete && i.naturalWidth > 0))
                            .map(i => i.getAttribute('src'));
  const formulas = document.querySelectorAll('script[type^="math/tex"]').length;
  return {mathjax, raw, texErrors, brokenImages, formulas, images: document.images.length};
})()
"""

# MathJax shows its progress ("Typesetting math: 100%", "Loading ...") in a box for a
# moment after typesetting: waits (at most 10 s) until the box is gone, so that the
# screenshot shows the page alone.
WAIT_FOR_MATHJAX_MESSAGE_JS = r"""
(async () => {
  for (let i = 0; i < 100; ++i) {
    const box = document.getElementById('MathJax_Message');
    if (!box || getComputedStyle(box).display === 'none' || !box.innerText.trim()) return true;
    await new Promise(r => setTimeout(r, 100));
  }
  return false;
})()
"""


class Browser:
    """A headless Chromium and one tab, driven over the DevTools pipe: fd 3 carries
    the commands to Chromium, fd 4 its answers and events, each a JSON text ended by NUL."""

    def __init__(self, executable, profile_dir, log_file):
        to_browser_r, self.to_browser = os.pipe()
        self.from_browser, from_browser_w = os.pipe()

        def give_pipes_to_child():
            # Move the child's ends to fds 3 and 4 without one overwriting the other.
            a = fcntl.fcntl(to_browser_r, fcntl.F_DUPFD_CLOEXEC, 10)
            b = fcntl.fcntl(from_browser_w, fcntl.F_DUPFD_CLOEXEC, 10)
            os.dup2(a, 3)
            os.dup2(b, 4)

        args = [executable, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--no-default-browser-check", "--disable-background-networking",
                "--disable-component-update", "--disable-sync", "--disable-extensions",
                "--disable-dev-shm-usage", "--hide-scrollbars", "--mute-audio",
                "--user-data-dir=" + profile_dir, "--remote-debugging-pipe", "about:blank"]
        self.process = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=log_file,
                                        stderr=log_file, close_fds=False,
                                        preexec_fn=give_pipes_to_child)
        os.close(to_browser_r)
        os.close(from_browser_w)
        self.buffer = b""
        self.next_id = 0
        self.answers = {}
        self.events = []
        self.session = None

    def close(self):
        try:
            self.send("Browser.close", session=None, wait=False)
        except OSError:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self.to_browser)
        os.close(self.from_browser)

    def _read(self, timeout):
        """Reads what Chromium sent within `timeout` seconds into answers and events."""
        ready, _, _ = select.select([self.from_browser], [], [], max(0.0, timeout))
        if not ready:
            return
        chunk = os.read(self.from_browser, 1 << 20)
        if not chunk:
            raise RuntimeError("Chromium closed the DevTools pipe (it exited with %s)"
                               % self.process.poll())
        self.buffer += chunk
        *messages, self.buffer = self.buffer.split(b"\0")
        for text in messages:
            message = json.loads(text)
            if "id" in message:
                self.answers[message["id"]] = message
            else:
                self.events.append(message)
                if message.get("method") == "Fetch.requestPaused":
                    # Only http(s) requests are paused (see open_tab): refuse them, as
                    # a machine without network access would.
                    self.send("Fetch.failRequest", {"requestId": message["params"]["requestId"],
                                                    "errorReason": "InternetDisconnected"},
                              wait=False)

    def send(self, method, params=None, session="tab", wait=True, timeout=30.0):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session == "tab":
            session = self.session
        if session:
            message["sessionId"] = session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        if not wait:
            return None
        key = self.next_id
        deadline = time.monotonic() + timeout
        while key not in self.answers:
            if time.monotonic() > deadline:
                raise RuntimeError("no answer from Chromium to %s within %g s" % (method, timeout))
            self._read(deadline - time.monotonic())
        answer = self.answers.pop(key)
        if "error" in answer:
            raise RuntimeError("%s: %s" % (method, answer["error"]))
        return answer["result"]

    def wait_for_event(self, method, timeout):
        deadline = time.monotonic() + timeout
        while True:
            for event in self.events:
                if event.get("method") == method and event.get("sessionId") == self.session:
                    return event
            if time.monotonic() > deadline:
                return None
            self._read(deadline - time.monotonic())

    def open_tab(self):
        target = self.send("Target.createTarget", {"url": "about:blank"}, session=None)
        self.session = self.send("Target.attachToTarget",
                                 {"targetId": target["targetId"], "flatten": True},
                                 session=None)["sessionId"]
        for domain in ("Page", "Runtime", "Log", "Network"):
            self.send(domain + ".enable")
        self.send("Fetch.enable", {"patterns": [{"urlPattern": "http://*"},
                                                {"urlPattern": "https://*"}]})
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": VIEWPORT[0], "height": VIEWPORT[1], "deviceScaleFactor": 1,
                   "mobile": False})

    def evaluate(self, expression, timeout):
        result = self.send("Runtime.evaluate",
                           {"expression": expression, "awaitPromise": True,
                            "returnByValue": True}, timeout=timeout)
        if "exceptionDetails" in result:
            raise RuntimeError("the check threw: %s" % result["exceptionDetails"])
        return result["result"].get("value")

    def screenshot(self, path):
        """What the window shows now."""
        data = self.send("Page.captureScreenshot",
                         {"format": "png", "captureBeyondViewport": False})["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))


def check_page(browser, html_dir, name):
    """Loads one page; returns the list of what is wrong on it and what the page showed."""
    url = "file://" + os.path.join(html_dir, name)
    browser.events.clear()
    navigation = browser.send("Page.navigate", {"url": url})
    if navigation.get("errorText"):
        return ["does not open: " + navigation["errorText"]], {}
    if browser.wait_for_event("Page.loadEventFired", LOAD_TIMEOUT) is None:
        return ["not loaded after %g s" % LOAD_TIMEOUT], {}
    seen = browser.evaluate(CHECK_PAGE_JS % {"timeout": TYPESET_TIMEOUT * 1000},
                            TYPESET_TIMEOUT + 30)
    browser._read(0)  # the events sent while the page was checked

    problems = []
    if seen["raw"]:
        problems.append("formulas shown as raw TeX (MathJax: %s): %s"
                        % (seen["mathjax"], " | ".join(seen["raw"])))
    elif seen["mathjax"] not in ("done", "not loaded"):
        problems.append("MathJax " + seen["mathjax"])
    for error in seen["texErrors"]:
        problems.append("TeX error shown instead of a formula: " + error)
    for src in seen["brokenImages"]:
        problems.append("broken image: " + str(src))

    urls = {}
    for event in browser.events:
        method, params = event.get("method"), event.get("params", {})
        if method == "Network.requestWillBeSent":
            url = urls[params["requestId"]] = params["request"]["url"]
            parsed = urllib.parse.urlparse(url)
            if parsed.scheme == "file":
                path = os.path.realpath(urllib.parse.unquote(parsed.path))
                if os.path.commonpath([path, html_dir]) != html_dir:
                    problems.append("loads a file from outside the manual's folder: " + path)
        elif method == "Network.loadingFailed":
            url = urls.get(params["requestId"], "?")
            if url.startswith(("http://", "https://")):
                problems.append("needs the network: " + url)
            else:
                problems.append("does not load %s: %s" % (url, params.get("errorText")))
        elif method == "Runtime.exceptionThrown":
            details = params["exceptionDetails"]
            description = details.get("exception", {}).get("description") or details.get("text")
            problems.append("JavaScript error: %s (%s:%s)" % (description, details.get("url", ""),
                                                              details.get("lineNumber")))
        elif method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
            problems.append("console error: " + " ".join(
                str(a.get("value", a.get("description", ""))) for a in params.get("args", [])))
        elif (method == "Log.entryAdded" and params["entry"].get("level") == "error"
              and params["entry"].get("source") != "network"):  # network: loadingFailed above
            problems.append("console error: " + params["entry"].get("text", ""))
    return problems, seen


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("html_dir")
    parser.add_argument("output_dir")
    parser.add_argument("--browser", help="Chromium's executable (default: found on the PATH)")
    parser.add_argument("--page", action="append",
                        help="check only this page (default: every .html of HTML_DIR)")
    args = parser.parse_args()

    browser_path = args.browser or next(filter(None, map(shutil.which, BROWSER_NAMES)), None)
    if not browser_path:
        print("chromium not found (Debian: chromium; scripts/setup.sh installs it): "
              "the manual was not checked in a browser")
        return SKIP
    html_dir = os.path.realpath(args.html_dir)
    if not os.path.isfile(os.path.join(html_dir, "index.html")):
        print("error: %s/index.html does not exist: build the manual first (target doc)" % html_dir)
        return 1
    pages = args.page or sorted(p for p in os.listdir(html_dir) if p.endswith(".html"))
    pages.sort(key=lambda p: p != "index.html")  # the user manual first
    os.makedirs(args.output_dir, exist_ok=True)

    start = time.monotonic()
    failed = {}
    formulas = 0
    images = 0
    with tempfile.TemporaryDirectory(prefix="heat_diffusion_chromium_") as profile, \
            open(os.path.join(args.output_dir, "chromium.log"), "wb") as log:
        browser = Browser(browser_path, profile, log)
        try:
            browser.open_tab()
            for page in pages:
                problems, seen = check_page(browser, html_dir, page)
                formulas += seen.get("formulas", 0)
                images += seen.get("images", 0)
                if problems:
                    failed[page] = problems
                if page == pages[0]:
                    output_dir = os.path.abspath(args.output_dir)
                    browser.evaluate(WAIT_FOR_MATHJAX_MESSAGE_JS, 30)
                    shot = os.path.join(output_dir, "first_page.png")
                    browser.screenshot(shot)
                    print("screenshot of %s: %s" % (page, shot))
        finally:
            browser.close()

    # A problem of many pages (a missing script, say) is reported once, with its pages.
    pages_of = {}
    for page, problems in failed.items():
        for problem in problems:
            pages_of.setdefault(problem, []).append(page)
    common = {p for p, where in pages_of.items() if len(where) > 3}
    for problem in sorted(common):
        where = pages_of[problem]
        print("error: %s\n  on %d pages: %s, ..." % (problem, len(where), ", ".join(where[:3])))
    for page, problems in failed.items():
        own = [p for p in problems if p not in common]
        if own:
            print("%s:" % os.path.join(html_dir, page))
            for problem in own:
                print("  error: " + problem)
    print("%d page(s) checked in %s (%d formulas, %d images) in %.0f s: %d with problems"
          % (len(pages), os.path.basename(browser_path), formulas, images,
             time.monotonic() - start, len(failed)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
