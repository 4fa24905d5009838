#!/usr/bin/env python3
"""The shopper's page in a real browser: headless Chromium (Debian's chromium and
chromium-driver, driven by python3-selenium) loads / from a figment-serve this test
starts, sees the picture of the shopper's made body, changes a measurement and a garment
and sees the picture change each time, on a phone-sized window, switches the fit map on
and sees the garments in its bands, and asks for size advice (GET /api/fit) for the women's
M chart body. Every case needs MakeHuman's data (the made body): where the file system has
none, each is skipped before it runs and the script exits 77, ctest's skip. Screenshots go
to SCREENSHOT-FOLDER.

    test_page.py FIGMENT-SERVE SCREENSHOT-FOLDER
"""
import os
import sys

from selenium import webdriver
from selenium.webdriver.chrome.service import Service as ChromeService
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

from ServeSupport import ServerCase, main, needs_makehuman

SCREENSHOTS = None
WAIT = 600  # s: WebDriverWait's bound, not an assertion on speed (a cold drape takes seconds)


class Page(ServerCase):
    server_arguments = ("--workers", "2")

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        options = webdriver.ChromeOptions()
        options.binary_location = "/usr/bin/chromium"
        for argument in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                         "--window-size=600,1300"):
            options.add_argument(argument)
        # A phone's screen: 390 CSS pixels wide, as the page is laid out there.
        options.add_experimental_option("mobileEmulation",
                                        {"deviceMetrics": {"width": 390, "height": 1000, "pixelRatio": 1}})
        cls.browser = webdriver.Chrome(service=ChromeService("/usr/bin/chromedriver"), options=options)

    @classmethod
    def tearDownClass(cls):
        cls.browser.quit()
        super().tearDownClass()

    def picture_query(self):
        return self.browser.find_element(By.ID, "picture").get_attribute("data-query") or ""

    def wait_for_new_picture(self, before):
        """Waits until the page shows a picture for another request than `before`, loaded."""
        WebDriverWait(self.browser, WAIT).until(
            lambda b: self.picture_query() not in ("", before) and b.execute_script(
                "const i = document.getElementById('picture'); return i.complete && i.naturalWidth > 0;"))
        return self.picture_query()

    def picture_pixels(self):
        """The shown picture's decoded pixels, summed per channel over a 48x64 sample (the
        page's own image, drawn into a canvas): what the shopper sees, not the URL."""
        return self.browser.execute_script(
            "const i = document.getElementById('picture'); const c = document.createElement('canvas');"
            "c.width = 48; c.height = 64; const g = c.getContext('2d'); g.drawImage(i, 0, 0, 48, 64);"
            "const d = g.getImageData(0, 0, 48, 64).data; const s = [0, 0, 0];"
            "for (let k = 0; k < d.length; k += 4) { s[0] += d[k]; s[1] += d[k + 1]; s[2] += d[k + 2]; }"
            "return s;")

    def assertPictureChanged(self, before):
        after = self.picture_pixels()
        self.assertNotEqual(after, before)
        return after

    def shot(self, name):
        os.makedirs(SCREENSHOTS, exist_ok=True)
        self.browser.execute_script("window.scrollTo(0, 0)")
        self.browser.save_screenshot(os.path.join(SCREENSHOTS, name))

    @needs_makehuman
    def test_changing_a_measurement_and_a_garment_changes_the_picture(self):
        browser = self.browser
        browser.get(self.server.url)
        first = self.wait_for_new_picture("")
        self.assertIn("outfit=dress%3AM", first)
        self.assertEqual(browser.find_element(By.ID, "error").text, "")
        pixels = self.picture_pixels()
        self.assertGreater(sum(pixels), 0)
        self.shot("serve-page.png")
        # Narrower than the viewport: usable on a phone without sideways scrolling.
        self.assertEqual(browser.execute_script("return window.innerWidth"), 390)
        self.assertLessEqual(browser.execute_script("return document.documentElement.scrollWidth"), 390)

        hips = browser.find_element(By.ID, "hips")
        hips.clear()
        hips.send_keys("100")
        browser.execute_script("arguments[0].dispatchEvent(new Event('change'))", hips)
        second = self.wait_for_new_picture(first)
        self.assertIn("hips=1.000", second)
        pixels = self.assertPictureChanged(pixels)

        Select(browser.find_element(By.ID, "style-0")).select_by_value("tshirt")
        Select(browser.find_element(By.ID, "style-1")).select_by_value("skirt")
        Select(browser.find_element(By.ID, "size-1")).select_by_value("L")
        third = self.wait_for_new_picture(second)
        self.assertIn("outfit=tshirt%3AM%3Ad9d9d1%2Cskirt%3AL%3A8c1f33", third)
        # The 3D download is the same outfit as glTF binary.
        self.assertTrue(browser.find_element(By.ID, "glb").get_attribute("href").endswith(third + "&format=glb"))
        pixels = self.assertPictureChanged(pixels)
        self.shot("serve-page-outfit.png")

        browser.find_element(By.ID, "turn-right").click()
        turned = self.wait_for_new_picture(third)
        self.assertIn("view=30%2C5", turned)
        self.assertPictureChanged(pixels)
        self.assertEqual(browser.find_element(By.ID, "error").text, "")
        self.shot("serve-page-turned.png")

    def band_pixels(self):
        """(warm, blue): the shown picture's pixels in the fit map's red to yellow bands (no
        blue in them) and in its blue band (blue alone), at the picture's own size. Neither
        the skin, the grey T-shirt nor the dark red skirt is either."""
        return self.browser.execute_script(
            "const i = document.getElementById('picture'); const c = document.createElement('canvas');"
            "c.width = i.naturalWidth; c.height = i.naturalHeight; const g = c.getContext('2d');"
            "g.drawImage(i, 0, 0); const d = g.getImageData(0, 0, c.width, c.height).data;"
            "let warm = 0, blue = 0;"
            "for (let k = 0; k < d.length; k += 4) { const s = d[k] + d[k + 1] + d[k + 2]; if (s <= 60) continue;"
            "  if (d[k + 2] < 0.08 * s && d[k] > 0.45 * s) warm++; if (d[k + 2] > 0.8 * s) blue++; }"
            "return [warm, blue];")

    @needs_makehuman
    def test_the_fit_map_colours_the_garments_by_their_stretch(self):
        browser = self.browser
        browser.get(self.server.url)
        first = self.wait_for_new_picture("")
        Select(browser.find_element(By.ID, "style-0")).select_by_value("tshirt")
        Select(browser.find_element(By.ID, "size-0")).select_by_value("S")
        Select(browser.find_element(By.ID, "style-1")).select_by_value("skirt")
        dressed = self.wait_for_new_picture(first)
        self.assertNotIn("fitmap", dressed)
        self.assertEqual(self.band_pixels(), [0, 0])
        self.assertTrue(browser.find_element(By.ID, "fitmap-legend").get_attribute("hidden"))
        browser.find_element(By.ID, "fitmap").click()
        mapped = self.wait_for_new_picture(dressed)
        self.assertIn("fitmap=stretch", mapped)
        warm, blue = self.band_pixels()
        # Most of the cloth hangs at rest (blue); the skirt's waistband holds it up, stretched.
        self.assertGreater(blue, 2000, (warm, blue))
        self.assertGreater(warm, 20, (warm, blue))
        self.assertFalse(browser.find_element(By.ID, "fitmap-legend").get_attribute("hidden"))
        self.assertEqual(browser.find_element(By.ID, "error").text, "")
        self.shot("serve-page-fitmap.png")

    @needs_makehuman
    def test_size_advice_names_the_chart_bodys_own_size(self):
        browser = self.browser
        browser.get(self.server.url)
        self.wait_for_new_picture("")
        for name, cm in (("stature", "168"), ("bust", "88"), ("waist", "72"), ("hips", "96")):
            field = browser.find_element(By.ID, name)
            field.clear()
            field.send_keys(cm)
        Select(browser.find_element(By.ID, "fit-style")).select_by_value("pencil")
        browser.find_element(By.ID, "advise").click()
        advice = browser.find_element(By.ID, "advice")
        WebDriverWait(browser, WAIT).until(lambda b: "Recommended" in advice.text or "error" in advice.text
                                           or "MakeHuman" in advice.text)
        self.assertIn("Recommended: M", advice.text)
        self.assertIn("M: fits everywhere", advice.text)
        self.assertLessEqual(browser.execute_script("return document.documentElement.scrollWidth"), 390)
        browser.execute_script("arguments[0].scrollIntoView()", advice)
        browser.save_screenshot(os.path.join(SCREENSHOTS, "serve-page-advice.png"))


if __name__ == "__main__":
    ServerCase.executable = sys.argv.pop(1)
    SCREENSHOTS = sys.argv.pop(1)
    main()
