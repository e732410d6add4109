#!/usr/bin/env python3
"""The page in a real browser: headless Chromium through WebDriver (Debian's chromium,
chromium-driver and python3-selenium), against `wobble serve` on a free port.

    browser_test.py WOBBLE SCREENSHOT_DIR

Opens the problem list and a problem at a variant; the math renders (KaTeX elements, no KaTeX
error); a right answer typed with Enter is accepted and the focus moves on; a wrong one gets its
named mistake, and after the second wrong try the part's hint appears; a reload comes back to the
same problem and variant; two browsers on different variants are judged each on their own
values; the browser logs no error. Screenshots are written to SCREENSHOT_DIR to look at.
Exits 77 (skipped) without the browser or its driver.
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


def expect(condition, message):
    if not condition:
        failures.append(message)


def fetch(url):
    opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))  # loopback, no proxy
    with opener.open(url, timeout=30) as r:
        return json.loads(r.read())


def browser():
    options = webdriver.ChromeOptions()
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1000,1400",
                "--disable-dev-shm-usage", "--no-proxy-server"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    service = webdriver.chrome.service.Service(executable_path=DRIVER)
    return webdriver.Chrome(service=service, options=options)


def wait_for(driver, css, seconds=20):
    return WebDriverWait(driver, seconds).until(
        lambda d: d.find_elements(By.CSS_SELECTOR, css) or False)


def answer_input(driver, name):
    return driver.find_element(By.CSS_SELECTOR, 'input[data-answer="%s"]' % name)


def verdict_of(driver, name):
    box = answer_input(driver, name).find_element(By.XPATH, "following-sibling::div")
    WebDriverWait(driver, 20).until(lambda d: box.text.strip() != "")
    return box


def main():
    wobble, shots = sys.argv[1], sys.argv[2]
    os.makedirs(shots, exist_ok=True)
    server = subprocess.Popen([wobble, "serve", "--port", "0"], stdout=subprocess.PIPE, text=True)
    drivers = []
    try:
        first = server.stdout.readline()
        base = re.search(r"http://[0-9.]+:\d+/", first).group(0)
        token = re.search(r"token: ([0-9a-f]+)", server.stdout.readline()).group(1)
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
        wait_for(d, ".part input")
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
        inputs = d.find_elements(By.CSS_SELECTOR, ".part:first-of-type input")
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
        d.save_screenshot(os.path.join(shots, "flying-plate-5.png"))
        # A reload comes back to the same problem and variant.
        d.refresh()
        wait_for(d, ".part input")
        variant = d.find_element(By.CSS_SELECTOR, ".variant input").get_attribute("value")
        expect(variant == "5" and "flying plate" in d.find_element(By.TAG_NAME, "h1").text.lower(),
               "after a reload: variant %r, %r" % (variant, d.find_element(By.TAG_NAME, "h1").text))
        # A second browser at the default values: variant 5's answer is wrong there.
        d2 = browser()
        drivers.append(d2)
        d2.get(base + "#/flying-plate")
        wait_for(d2, ".part input")
        answer_input(d2, "I0").send_keys(right, Keys.ENTER)
        v2 = verdict_of(d2, "I0")
        expect(v2.text.startswith("incorrect"), "variant 5's answer at the defaults: %r" % v2.text)
        for driver in drivers:
            # The unreadable answer typed on purpose is refused with a 400, which the browser
            # logs; anything else is an error.
            severe = [e for e in driver.get_log("browser") if e["level"] == "SEVERE" and
                      not ("/check" in e["message"] and "status of 400" in e["message"])]
            expect(not severe, "browser errors: %s" % severe)
    finally:
        for driver in drivers:
            driver.quit()
        server.terminate()
        server.wait(timeout=10)
    print("browser: list, typeset math, right, named mistake, hint, reload, two variants;"
          " screenshots in %s" % shots)
    if failures:
        print("\n".join(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
