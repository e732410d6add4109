#!/usr/bin/env python3
"""The page in a real browser: headless Chromium through WebDriver (Debian's chromium,
chromium-driver and python3-selenium), against `wobble serve` on a free port.

    browser_test.py WOBBLE SCREENSHOT_DIR

Opens the problem list and a problem at a variant; the math renders (KaTeX elements, no KaTeX
error); a right answer typed with Enter is accepted and the focus moves on; a wrong one gets its
named mistake, and after the second wrong try the part's hint appears; a reload comes back to the
same problem and variant; two browsers on different variants are judged each on their own
values; the browser logs no error. The 3-D view draws (its canvas is not blank) and moves (the
red e3 arrow's pixels are elsewhere at two times), for a problem, the heavy top, the tennis
racket and a scene; its frames per second are measured. The instructor's page (the token in the
address) shows the key, and every key value pasted back into its box is judged right. The page
written by `wobble page` works from a file URL: math, 3-D view, the key only with --key.
Screenshots are written to SCREENSHOT_DIR to look at. Exits 77 (skipped) without the browser or
its driver.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import time
import urllib.request

try:
    from selenium import webdriver
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError:
    print("SKIPPED: this test needs python3-selenium (scripts/setup --tests)")
    sys.exit(77)

DRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"
if not os.path.exists(DRIVER):
    print("SKIPPED: this test needs chromium-driver (scripts/setup --tests)")
    sys.exit(77)

failures = []


START = time.monotonic()


def stage(what):
    print("%6.1f s  %s" % (time.monotonic() - START, what), flush=True)


def expect(condition, message):
    if not condition:
        failures.append(message)


def fetch(url):
    opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))  # loopback, no proxy
    with opener.open(url, timeout=30) as r:
        return json.loads(r.read())


def browser():
    options = webdriver.ChromeOptions()
    # WebGL without a GPU: SwiftShader, which Chromium now uses only when asked.
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1000,1400",
                "--disable-dev-shm-usage", "--no-proxy-server", "--enable-unsafe-swiftshader"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    service = webdriver.chrome.service.Service(executable_path=DRIVER)
    return webdriver.Chrome(service=service, options=options)


# Selects an element and copies it as a reader's Ctrl+C does, returning the text/plain copied.
COPY_SCRIPT = """
const range = document.createRange();
range.selectNode(arguments[0]);
const selection = window.getSelection();
selection.removeAllRanges();
selection.addRange(range);
const data = new DataTransfer();
document.dispatchEvent(new ClipboardEvent('copy', {clipboardData: data, bubbles: true,
                                                   cancelable: true}));
return data.getData('text/plain');
"""


def wait_for(driver, css, seconds=20):
    return WebDriverWait(driver, seconds).until(
        lambda d: d.find_elements(By.CSS_SELECTOR, css) or False)


def answer_input(driver, name):
    return driver.find_element(By.CSS_SELECTOR, '[data-answer="%s"]' % name)


def verdict_of(driver, name):
    box = answer_input(driver, name).find_element(By.XPATH, "following-sibling::div")
    WebDriverWait(driver, 20).until(lambda d: box.text.strip() != "")
    return box


# The 3-D canvas read back: how many of its pixels are not the background, and where the pure red
# of the e3 arrow is (count, centre x, centre y).
CANVAS_PIXELS = """
const c = document.querySelector('canvas.view3d');
const off = document.createElement('canvas');
off.width = c.width; off.height = c.height;
const g = off.getContext('2d');
g.drawImage(c, 0, 0);
const d = g.getImageData(0, 0, c.width, c.height).data;
let red = 0, x = 0, y = 0, drawn = 0;
for (let i = 0; i < d.length; i += 4) {
  const r = d[i], gr = d[i + 1], b = d[i + 2], p = i / 4;
  if (r > 200 && gr < 70 && b < 70) { red += 1; x += p % c.width; y += Math.floor(p / c.width); }
  if (Math.abs(r - 0xf4) + Math.abs(gr - 0xf6) + Math.abs(b - 0xfa) > 30) drawn += 1;
}
return [drawn / (d.length / 4), red, red ? x / red : 0, red ? y / red : 0];
"""


def view_at(driver, t):
    driver.execute_script("window.wobbleView.pause(); window.wobbleView.setTime(arguments[0]);", t)
    return driver.execute_script(CANVAS_PIXELS)


def check_view(driver, name, shots):
    """The 3-D view on the page drawn and moving; returns its frames per second while playing."""
    WebDriverWait(driver, 20).until(lambda d: d.execute_script("return !!window.wobbleView"))
    T = driver.execute_script("return window.wobbleView.duration")
    drawn, red, x0, y0 = view_at(driver, 0.0)
    expect(drawn > 0.02, "%s: the 3-D view is blank (%.4f of its pixels drawn)" % (name, drawn))
    expect(red > 20, "%s: no e3 arrow at t = 0 (%d red pixels)" % (name, red))
    driver.save_screenshot(os.path.join(shots, name + "-t0.png"))
    _, red1, x1, y1 = view_at(driver, T / 4)
    moved = ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5
    expect(red1 > 20 and moved > 5, "%s: e3 did not move between t = 0 and %g s (%.1f px)"
           % (name, T / 4, moved))
    driver.save_screenshot(os.path.join(shots, name + "-t1.png"))
    driver.execute_script("window.wobbleView.play()")
    before = driver.execute_script("return window.wobbleView.rendered")
    time.sleep(2)
    fps = (driver.execute_script("return window.wobbleView.rendered") - before) / 2
    expect(fps > 0, "%s: the view does not animate" % name)
    return fps


MATH = re.compile(r"\$\$(.+?)\$\$|\$(.+?)\$", re.S)


def check_catalog_math(driver, base):
    """Every statement's, parameter's, question's and hint's math, every problem, through KaTeX
    with errors thrown (as the page loads it): what a student sees is typeset, never KaTeX's red
    source."""
    texts = []
    for p in fetch(base + "api/problems"):
        view = fetch(base + "api/problems/" + p["id"])
        texts.append((p["id"] + " statement", view["statement"]))
        texts += [("%s %s" % (p["id"], q["name"]), q["description"]) for q in view["parameters"]]
        for part in view["parts"]:
            texts.append(("%s (%s)" % (p["id"], part["id"]), part["question"]))
            if part["has_hint"]:
                hint = fetch(base + "api/problems/%s/hint?part=%s" % (p["id"], part["id"]))
                texts.append(("%s (%s) hint" % (p["id"], part["id"]), hint["hint"]))
    formulas = [(where, a or b) for where, text in texts for a, b in MATH.findall(text)]
    errors = driver.execute_script("""
      const bad = [];
      for (const [where, tex] of arguments[0]) {
        try { katex.renderToString(tex, {throwOnError: true}); }
        catch (e) { bad.push(where + ': ' + tex + ': ' + e.message); }
      }
      return bad;""", formulas)
    expect(len(formulas) > 200, "only %d formulas in the catalog's texts" % len(formulas))
    expect(not errors, "KaTeX cannot typeset: %s" % "; ".join(errors[:5]))
    stage("the catalog's math: %d formulas typeset" % len(formulas))


def vertical_scrollbars(driver):
    """The boxes that show a vertical scrollbar: content taller than the box where the box
    scrolls (overflow-x: auto makes overflow-y auto too, and KaTeX's radical reaches a pixel
    below its line). KaTeX's own hidden MathML is no box a student sees."""
    return driver.execute_script("""
      return Array.from(document.querySelectorAll('body *')).filter(e => {
        const style = getComputedStyle(e);
        return !e.closest('.katex') && ['auto', 'scroll'].includes(style.overflowY) &&
               e.scrollHeight > e.clientHeight;
      }).map(e => e.className + ': ' + e.textContent.slice(0, 40));""")


def severe_errors(driver):
    # The unreadable answer typed on purpose is refused with a 400, which the browser logs;
    # anything else is an error.
    return [e for e in driver.get_log("browser") if e["level"] == "SEVERE" and
            not ("/check" in e["message"] and "status of 400" in e["message"])]


def main():
    wobble, shots = sys.argv[1], sys.argv[2]
    os.makedirs(shots, exist_ok=True)
    server = subprocess.Popen([wobble, "serve", "--port", "0"], stdout=subprocess.PIPE, text=True)
    drivers = []
    try:
        first = server.stdout.readline()
        base = re.search(r"http://[0-9.]+:\d+/", first).group(0)
        token = re.search(r"token=([0-9a-f]+)", server.stdout.readline()).group(1)
        key = fetch(base + "api/problems/flying-plate/key?variant=5&token=" + token)
        i0 = key["parts"][0]["answers"][0]
        right = "%r %s" % (i0["value"], i0["unit"])

        d = browser()
        drivers.append(d)
        d.get(base)
        links = wait_for(d, "ul.problems a")
        expect(len(links) >= 15, "the list shows %d problems" % len(links))
        d.save_screenshot(os.path.join(shots, "list.png"))
        d.get(base + "#/flying-plate/5")
        wait_for(d, ".part [data-answer]")
        expect(len(d.find_elements(By.CSS_SELECTOR, ".katex")) > 0, "no math typeset")
        expect(not d.find_elements(By.CSS_SELECTOR, ".katex-error"), "KaTeX error elements")
        box = answer_input(d, "I0")
        box.send_keys(right, Keys.ENTER)
        v = verdict_of(d, "I0")
        expect("right" in v.get_attribute("class") and v.text.startswith("correct"),
               "the right answer: %r" % v.text)
        active = d.switch_to.active_element.get_attribute("data-answer")
        expect(active and active != "I0", "the focus stayed on I0 (%s)" % active)
        # Part (a)'s next answer, twice wrong: the mistake named, then the hint.
        inputs = d.find_elements(By.CSS_SELECTOR, ".part:first-of-type [data-answer]")
        name = active
        answer = next(a for p in key["parts"] for a in p["answers"] if a["name"] == name)
        twice = json.dumps([2 * x for x in answer["value"]] if isinstance(answer["value"], list)
                           and not isinstance(answer["value"][0], list) else
                           [[2 * x for x in row] for row in answer["value"]]
                           if isinstance(answer["value"], list) else 2 * answer["value"])
        target = answer_input(d, name)
        target.send_keys(twice + " " + answer["unit"], Keys.ENTER)
        v = verdict_of(d, name)
        expect("2 times the answer" in v.text, "doubled %s: %r" % (name, v.text))
        target.clear()
        target.send_keys("12345", Keys.ENTER)
        hint = WebDriverWait(d, 20).until(
            lambda dr: [h for h in dr.find_elements(By.CSS_SELECTOR, ".hint") if h.is_displayed()])
        expect(hint and hint[0].text.startswith("Hint:"), "no hint after two wrong tries")
        expect(hint and hint[0].find_elements(By.CSS_SELECTOR, ".katex") and
               not hint[0].find_elements(By.CSS_SELECTOR, ".katex-error"),
               "the hint's math is not typeset")
        # A refusal under its box names no request field ("answer: .."): the box is the answer.
        target.clear()
        target.send_keys("[[1, 2], [3, 4]]", Keys.ENTER)
        WebDriverWait(d, 20).until(lambda dr: "2x2" in verdict_of(dr, name).text)
        refused = verdict_of(d, name).text
        expect(refused.startswith(name + " wants a 3x3 matrix"),
               "the refusal under %s: %r" % (name, refused))
        # The matrix pasted as MATLAB prints it, a row on each line: the box keeps the lines (an
        # input strips them, and "-0.75⏎-0.5" became the difference -0.75-0.5) and grows to
        # show them; Enter judges it.
        expect(answer["shape"] == "matrix" if "shape" in answer else
               isinstance(answer["value"][0], list), "part (a)'s second answer is no matrix")
        rows = "\n".join(" ".join("%r" % x for x in row) for row in answer["value"])
        target.clear()
        d.execute_script("arguments[0].value = arguments[1];"
                         "arguments[0].dispatchEvent(new Event('input'));", target, rows)
        expect(target.get_attribute("value") == rows, "the pasted rows lost their line breaks")
        expect(target.get_attribute("rows") == str(len(answer["value"])),
               "the box shows %s lines of %d" % (target.get_attribute("rows"), len(answer["value"])))
        d.save_screenshot(os.path.join(shots, "flying-plate-5-rows.png"))
        target.send_keys(Keys.END, Keys.ENTER)
        WebDriverWait(d, 20).until(lambda dr: verdict_of(dr, name).text.startswith("correct"))
        # An Enter that confirms an input method's composition judges nothing.
        composing = answer_input(d, "L0_body")
        composing.send_keys("0.1")
        d.execute_script("arguments[0].dispatchEvent(new KeyboardEvent('keydown',"
                         "{key: 'Enter', isComposing: true, bubbles: true}));", composing)
        time.sleep(1)
        later = composing.find_element(By.XPATH, "following-sibling::div").text
        expect(later == "", "an IME's Enter was judged: %r" % later)
        composing.clear()
        check_catalog_math(d, base)
        d.save_screenshot(os.path.join(shots, "flying-plate-5.png"))
        # A reload comes back to the same problem and variant.
        d.refresh()
        wait_for(d, ".part [data-answer]")
        variant = d.find_element(By.CSS_SELECTOR, ".variant input").get_attribute("value")
        expect(variant == "5" and "flying plate" in d.find_element(By.TAG_NAME, "h1").text.lower(),
               "after a reload: variant %r, %r" % (variant, d.find_element(By.TAG_NAME, "h1").text))
        # A second browser at the default values: variant 5's answer is wrong there.
        d2 = browser()
        drivers.append(d2)
        d2.get(base + "#/flying-plate")
        wait_for(d2, ".part [data-answer]")
        answer_input(d2, "I0").send_keys(right, Keys.ENTER)
        v2 = verdict_of(d2, "I0")
        expect(v2.text.startswith("incorrect"), "variant 5's answer at the defaults: %r" % v2.text)
        # The 3-D views: a torque-free top with its cones, the heavy top, the racket, a scene.
        stage("worksheet done")
        fps = {}
        d.get(base + "#/flying-plate/5")
        wait_for(d, ".part [data-answer]")
        fps["flying-plate"] = check_view(d, "view-flying-plate", shots)
        for path, name in (("#/heavy-top/3", "view-heavy-top"),
                           ("#/tennis-racket", "view-tennis-racket"),
                           ("#/scene/wheel-brake", "view-scene-wheel-brake")):
            d.get(base + path)
            d.refresh()
            wait_for(d, "canvas.view3d")
            fps[name] = check_view(d, name, shots)
            if name == "view-tennis-racket":
                # Each label says how its answer is typed, its entries as the question names
                # them: the pair (Ω₂, Ω₃) and the coefficients c₁.. are no x, y, z, and the
                # body's components are along e₁, e₂, e₃.
                labels = {l.text.split()[0]: l.text
                          for l in d.find_elements(By.CSS_SELECTOR, ".answer label")}
                for name, form in (("Omega_axis1", "(a vector [Ω₂, Ω₃])"),
                                   ("Omega_axis2", "(a vector [Ω₃, Ω₁])"),
                                   ("euler_coefficients", "(a vector [c₁, c₂, c₃])"),
                                   ("dw_dt0", "(a vector [.., .., ..] along e₁, e₂, e₃)")):
                    expect(labels.get(name, "").endswith(form),
                           "%s's label: %r" % (name, labels.get(name)))
        stage("3-D views done")
        # The instructor's page: the key under each answer, each one judged right pasted back.
        for other in (d, d2):
            other.get(base)  # the list: their views stop drawing, leaving the CPU to this one
        d3 = browser()
        drivers.append(d3)
        d3.get(base + "?token=" + token + "#/flying-plate/5")
        wait_for(d3, ".key-value")
        # Paused: software WebGL drawing 60 frames a second slows the typing (tens of seconds).
        d3.execute_script("window.wobbleView.pause()")
        boxes = d3.find_elements(By.CSS_SELECTOR, ".answer [data-answer]")
        values = d3.find_elements(By.CSS_SELECTOR, ".key-value")
        expect(len(values) == len(boxes) > 5, "the key shows %d values for %d answers"
               % (len(values), len(boxes)))
        for box, value in zip(boxes, values):
            box.send_keys(value.text, Keys.ENTER)
            name = box.get_attribute("data-answer")
            v = verdict_of(d3, name)
            expect(v.text.startswith("correct"), "the key's %s pasted back (%r): %r"
                   % (name, value.text, v.text))
        # Each typeset closed form copied as the browser copies it (LaTeX, by KaTeX's copy-tex)
        # and pasted back: judged right.
        copied_forms = 0
        for answer in d3.find_elements(By.CSS_SELECTOR, ".answer"):
            formulas = answer.find_elements(By.CSS_SELECTOR, ".key-answer .katex")
            if not formulas:
                continue
            copied = d3.execute_script(COPY_SCRIPT, formulas[0])
            box = answer.find_element(By.CSS_SELECTOR, "[data-answer]")
            name = box.get_attribute("data-answer")
            expect(copied.startswith("$") and copied.endswith("$"),
                   "%s: the copy is no LaTeX: %r" % (name, copied))
            box.clear()
            box.send_keys(copied, Keys.ENTER)
            v = verdict_of(d3, name)
            expect(v.text.startswith("correct"), "the key's %s copied as LaTeX (%r): %r"
                   % (name, copied, v.text))
            copied_forms += 1
        expect(copied_forms > 5, "only %d typeset forms copied" % copied_forms)
        d3.save_screenshot(os.path.join(shots, "instructor-flying-plate-5.png"))
        # A top too slow to precess steadily: part (d)'s answers do not exist, and are asked all
        # the same, in their unit; the key's "none at these values" pasted back is right.
        slow = next(n for n in range(1, 21)
                    if not fetch(base + "api/problems/heavy-top/key?variant=%d&token=%s"
                                 % (n, token))["parts"][3]["answers"])
        d3.get(base + "?token=" + token + "#/heavy-top/%d" % slow)
        d3.refresh()
        wait_for(d3, ".key-value")
        d3.execute_script("window.wobbleView.pause()")
        for name in ("phidot_slow", "phidot_fast"):
            box = answer_input(d3, name)
            answer = box.find_element(By.XPATH, "..")
            label = answer.find_element(By.TAG_NAME, "label").text
            expect(label == name + " [rad/s]", "an answer that does not exist: label %r" % label)
            value = answer.find_element(By.CSS_SELECTOR, ".key-value").text
            expect(value == "none at these values", "%s's key: %r" % (name, value))
            box.send_keys(value, Keys.ENTER)
            v = verdict_of(d3, name)
            expect(v.text.startswith("correct: %s does not exist" % name),
                   "%s's key pasted back: %r" % (name, v.text))
        d3.save_screenshot(os.path.join(shots, "instructor-heavy-top-slow.png"))
        expect(not d.find_elements(By.CSS_SELECTOR, ".key-value"), "a student sees the key")
        stage("instructor's page done")
        # The page as one file, opened from disk: no server, no network.
        for problem, extra, keyed in (("heavy-top", ["--variant", "3"], False),
                                      ("flying-plate", ["--key", "--no-hints"], True),
                                      ("tennis-racket", ["--key", "--no-hints"], True)):
            out = os.path.join(shots, problem + "-page.html")
            if os.path.exists(out):
                os.remove(out)
            subprocess.run([wobble, "page", problem, "--out", out] + extra, check=True,
                           stdout=subprocess.DEVNULL)
            d4 = browser()
            d4.get("file://" + out)
            wait_for(d4, ".part")
            expect(len(d4.find_elements(By.CSS_SELECTOR, ".katex")) > 0 and
                   not d4.find_elements(By.CSS_SELECTOR, ".katex-error"),
                   "%s page from disk: math not typeset" % problem)
            # Each part's hint folded under it, its math typeset when opened; none with --no-hints.
            folded = d4.find_elements(By.CSS_SELECTOR, "details.hint")
            expect(len(folded) == (0 if "--no-hints" in extra else 4),
                   "%s page from disk: %d folded hints" % (problem, len(folded)))
            if folded:
                d4.execute_script("arguments[0].scrollIntoView({block: 'center'})", folded[0])
                folded[0].find_element(By.TAG_NAME, "summary").click()
                expect(folded[0].get_attribute("open") is not None and
                       folded[0].find_elements(By.CSS_SELECTOR, ".katex") and
                       not folded[0].find_elements(By.CSS_SELECTOR, ".katex-error"),
                       "%s page from disk: the opened hint's math is not typeset" % problem)
                d4.save_screenshot(os.path.join(shots, "file-" + problem + "-hint.png"))
            check_view(d4, "file-" + problem, shots)
            scrolling = vertical_scrollbars(d4)
            expect(not scrolling, "%s page from disk: a box with a vertical scrollbar: %s"
                   % (problem, scrolling[:3]))
            shown = len(d4.find_elements(By.CSS_SELECTOR, ".key-value"))
            expect((shown > 0) == keyed, "%s page from disk: %d key values (key asked: %s)"
                   % (problem, shown, keyed))
            severe = severe_errors(d4)
            expect(not severe, "%s page from disk: browser errors: %s" % (problem, severe))
            d4.quit()
        for driver in drivers:
            severe = severe_errors(driver)
            expect(not severe, "browser errors: %s" % severe)
        print("3-D view, frames per second in headless Chromium (software WebGL): " +
              ", ".join("%s %.0f" % (k, v) for k, v in fps.items()))
    finally:
        for driver in drivers:
            driver.quit()
        server.terminate()
        server.wait(timeout=10)
    print("browser: list, typeset math, right, named mistake, hint, reload, two variants, 3-D"
          " views, instructor's key, the page from disk; screenshots in %s" % shots)
    if failures:
        print("\n".join(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
