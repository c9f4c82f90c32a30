"""Takes the README's picture of the viewer, docs/img/viewer.png:

    ./build/orthoray render docs/img/maze.scene --html maze.html
    /usr/bin/python3 tests/browser/take_screenshot.py maze.html docs/img/viewer.png

in headless Chromium, with the slider at step 9 and the pointer over a
reflection point, so the picture shows the exact read-out."""

import pathlib
import sys

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By


def main(page, picture):
    options = webdriver.ChromeOptions()
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=820,660",
                 "--hide-scrollbars"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    try:
        driver.get(pathlib.Path(page).resolve().as_uri())
        driver.execute_script("const s = document.getElementById('step'); s.value = 9;"
                              "s.dispatchEvent(new Event('input'));")
        points = driver.find_elements(By.CSS_SELECTOR, "#points circle.point:not(.hidden)")
        ActionChains(driver).move_to_element(points[min(5, len(points) - 1)]).perform()
        driver.save_screenshot(picture)
    finally:
        driver.quit()


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
