"""The interactive viewer (`orthoray render --html`, docs/render.md) in a
real browser: Debian's headless Chromium, driven by Selenium. For a 2D
path, a 3D path and an illumination scene the page must draw the scene's
elements and the expected segments, show the answer, hide segments as the
step slider moves back (and move the ray's head), play the path to its
end, zoom on the wheel, read out exact coordinates on hover, rotate in 3D,
draw a puzzle's grid, and paint the ray's colour in a screenshot. Without chromium, chromedriver or python3-selenium the session
exits with status 77 (conftest.py), which ctest reports as skipped."""

import os
import pathlib
import re
import shutil
import subprocess

import pytest

from png_pixels import read_png

CLI = os.environ.get("ORTHORAY_CLI", "orthoray")
SOURCE = pathlib.Path(os.environ.get("ORTHORAY_SOURCE_DIR", "."))
OUT = pathlib.Path(os.environ.get("ORTHORAY_BROWSER_OUT", "browser-test-output"))

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
DRIVER = shutil.which("chromedriver")

# The first segments' colour (amber, the start of the shading ramp) and the
# mirrors' blue, as the viewer's style sheet paints them.
AMBER = (240, 163, 10)
MIRROR_BLUE = (31, 95, 168)

# One splitter: the ray from (0, 1) along +x splits at (2, 1), on through
# (4, 1), lighting target 1, and back along -x; both escape. Three states,
# three segments; target 2 at (2, 3) is never reached.
SPLIT_SCENE = """dim 2
splitter x 2 y 0 4
ray 0 1 1 0
target 4 1
target 2 3
"""


@pytest.fixture(scope="module")
def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1000,900",
                 "--disable-dev-shm-usage"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(DRIVER), options=options)
    yield driver
    driver.quit()


def render(scene, name):
    OUT.mkdir(parents=True, exist_ok=True)
    page = OUT / (name + ".html")
    result = subprocess.run([CLI, "render", str(scene), "--html", str(page), "--quiet"],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("wrote " + str(page))
    return page


def load(browser, page):
    browser.get(page.resolve().as_uri())
    assert browser.find_element(By.TAG_NAME, "body").get_attribute("data-ready") == "true"


def count(browser, selector):
    return len(browser.find_elements(By.CSS_SELECTOR, selector))


def visible_segments(browser):
    return count(browser, "#segments line:not(.hidden)")


def move_slider(browser, value):
    browser.execute_script(
        "const s = document.getElementById('step'); s.value = arguments[0];"
        "s.dispatchEvent(new Event('input'));", value)


def head(browser):
    h = browser.find_element(By.ID, "head")
    return float(h.get_attribute("cx")), float(h.get_attribute("cy"))


def view_width(browser):
    return browser.execute_script("return document.getElementById('picture').viewBox.baseVal.width")


def hover_text(browser, selector, index=0):
    target = browser.find_elements(By.CSS_SELECTOR, selector)[index]
    ActionChains(browser).move_to_element(target).perform()
    return browser.find_element(By.ID, "readout").text


def has_colour(rows, colour, tolerance=12):
    return any(all(abs(p[c] - colour[c]) <= tolerance for c in range(3)) for row in rows for p in row)


def check_screenshot(browser, name):
    png = browser.find_element(By.ID, "stage").screenshot_as_png
    (OUT / (name + ".png")).write_bytes(png)
    _, _, rows = read_png(png)
    coloured = sum(1 for row in rows for p in row if min(p) < 200)
    assert coloured > 500, "the picture is blank"
    assert has_colour(rows, AMBER), "the ray's first colour is not on the screen"
    return rows


def test_2d_path(browser):
    page = render(SOURCE / "instances/2d/fractions-and-decimals.scene", "path-2d")
    text = page.read_text()
    assert "http://" not in text.replace('"http://www.w3.org/2000/svg"', "")
    load(browser, page)
    answer = browser.find_element(By.ID, "answer").text
    assert answer == "answer yes, reason hit, 3 reflections"
    reflections = int(re.search(r"(\d+) reflections", answer).group(1))
    # Three mirrors; each reflection's segment, then the last piece to the target.
    assert count(browser, "#elements line") == 3
    assert count(browser, "#segments line") == reflections + 1
    assert visible_segments(browser) == reflections + 1
    end = head(browser)
    move_slider(browser, 1)
    assert visible_segments(browser) == 1
    assert head(browser) != end
    assert browser.find_element(By.ID, "step-label").text.startswith("step 1 of 4")
    # The first reflection point, exactly (the scene's comment derives it);
    # the first point is the start, under the start's marker.
    assert hover_text(browser, "#points circle.point:not(.hidden)", 1) == "point (5/2, 5/4)"
    assert hover_text(browser, "#elements line") == "mirror x = 5/2, y in [0, 3/2] (line 13)"
    # Play from step 0 runs the slider to the end, then offers play again
    # (waited for, with a guard, not timed).
    move_slider(browser, 0)
    browser.find_element(By.ID, "play").click()
    WebDriverWait(browser, 20).until(
        lambda b: visible_segments(b) == 4 and b.find_element(By.ID, "play").text == "play")
    assert head(browser) == end
    # The wheel zooms in around the pointer: the view box narrows.
    width = view_width(browser)
    browser.execute_script(
        "const s = document.getElementById('picture'); const r = s.getBoundingClientRect();"
        "s.dispatchEvent(new WheelEvent('wheel', {deltaY: -300, clientX: r.x + r.width / 2,"
        " clientY: r.y + r.height / 2, bubbles: true, cancelable: true}));")
    zoomed = view_width(browser)
    assert zoomed < width * 0.8
    browser.find_element(By.ID, "reset-view").click()
    rows = check_screenshot(browser, "path-2d")
    assert has_colour(rows, MIRROR_BLUE)


def test_3d_path_rotates(browser):
    page = render(SOURCE / "instances/3d/box-corner-2x3x5.scene", "path-3d")
    load(browser, page)
    answer = browser.find_element(By.ID, "answer").text
    assert answer == "answer yes, reason hit, 21 reflections"
    assert count(browser, "#elements polygon") == 6
    assert count(browser, "#segments line") == 22
    first = browser.find_element(By.CSS_SELECTOR, "#segments line")
    before = first.get_attribute("x1"), first.get_attribute("y1")
    ActionChains(browser).move_to_element(browser.find_element(By.ID, "stage")) \
        .click_and_hold().move_by_offset(60, 25).release().perform()
    assert (first.get_attribute("x1"), first.get_attribute("y1")) != before
    assert hover_text(browser, "#markers circle.start").startswith("ray 1: start (")
    browser.find_element(By.ID, "reset-view").click()
    assert (first.get_attribute("x1"), first.get_attribute("y1")) == before
    check_screenshot(browser, "path-3d")


def test_illumination_branches(browser):
    OUT.mkdir(parents=True, exist_ok=True)
    scene = OUT / "split.scene"
    scene.write_text(SPLIT_SCENE)
    page = render(scene, "branches")
    load(browser, page)
    assert browser.find_element(By.ID, "answer").text == "answer no, reason unlit"
    assert "targets: 1 of 2 lit" in browser.find_element(By.ID, "caption").text
    assert count(browser, "#elements line.splitter") == 1
    assert count(browser, "#segments line") == 3
    assert count(browser, "#markers circle.target.lit") == 1
    assert count(browser, "#markers circle.target.unlit") == 1
    move_slider(browser, 0)
    assert visible_segments(browser) == 0
    move_slider(browser, 3)
    assert visible_segments(browser) == 3
    assert hover_text(browser, "#markers circle.target.unlit") == "target 2 (unlit): (2, 3)"
    check_screenshot(browser, "branches")


def test_puzzle_grid(browser):
    page = OUT / "puzzle.html"
    level = SOURCE / "tests/fuzz/corpus/lazor/three-reflect.bff"
    result = subprocess.run([CLI, "puzzle", "solve", str(level), "--render", str(page)],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    load(browser, page)
    assert browser.find_element(By.ID, "answer").text.startswith("answer yes")
    # A 3 x 3 grid has 4 + 4 lines; three blocks, four one-sided edges each.
    assert count(browser, "#grid line") == 8
    assert count(browser, "#elements line.mirror") == 12
    assert count(browser, "#markers circle.target.lit") == 1
    check_screenshot(browser, "puzzle")
