"""Headless Chromium driven by Selenium, shared by the page tests (test_viewer.py,
test_convergence_page.py). Debian: chromium, chromium-driver, python3-selenium. Without them a
test file skips itself with the reason, unless ZDG_REQUIRE_BROWSER=1 (CI), where that is a
failure: a skip there would hide the page tests."""
import os
import shutil


def missing_message(who):
    """"" when the browser, its driver and Selenium are installed; otherwise the reason, naming
    the packages to install. Raises RuntimeError under ZDG_REQUIRE_BROWSER=1."""
    missing = [name for name, ok in (("chromium", shutil.which("chromium")),
                                      ("chromium-driver", shutil.which("chromedriver")))
               if not ok]
    try:
        import selenium.webdriver  # noqa: F401
    except ImportError:
        missing.append("python3-selenium")
    if not missing:
        return ""
    message = who + " need a browser: apt-get install " + " ".join(missing)
    if os.environ.get("ZDG_REQUIRE_BROWSER") == "1":
        raise RuntimeError(message + " (ZDG_REQUIRE_BROWSER=1)")
    return message


def chromium(width, height):
    """A headless Chromium of this window size with software WebGL (swiftshader), keeping the
    browser's console log; the caller quits it."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    opts = webdriver.ChromeOptions()
    opts.binary_location = shutil.which("chromium")
    for a in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
              f"--window-size={width},{height}", "--use-angle=swiftshader",
              "--enable-unsafe-swiftshader", "--disable-extensions"):
        opts.add_argument(a)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=opts)
