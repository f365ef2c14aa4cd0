"""A window that shows an environment's pictures as it steps (render_mode="human"), drawn with
matplotlib: the pictures come from tendril's rasterizer, matplotlib only puts them on screen."""
import time


class Viewer:
    def __init__(self, title):
        import matplotlib.pyplot as plt

        self._plt = plt
        self._figure = None
        self._image = None
        self._title = title
        self._last = None

    def show(self, picture, seconds_per_frame):
        """Shows `picture` (height x width x 3 uint8) and keeps to the environment's time."""
        plt = self._plt
        if self._figure is None or not plt.fignum_exists(self._figure.number):
            height, width = picture.shape[:2]
            self._figure = plt.figure(self._title, figsize=(width / 100, height / 100), dpi=100)
            axes = self._figure.add_axes((0, 0, 1, 1))
            axes.set_axis_off()
            self._image = axes.imshow(picture)
            plt.show(block=False)
        else:
            self._image.set_data(picture)
        self._figure.canvas.draw_idle()
        wait = seconds_per_frame
        if self._last is not None:
            wait -= time.monotonic() - self._last
        self._figure.canvas.start_event_loop(max(wait, 1e-3))
        self._last = time.monotonic()

    @property
    def figure(self):
        return self._figure

    def close(self):
        if self._figure is not None:
            self._plt.close(self._figure)
            self._figure = None
