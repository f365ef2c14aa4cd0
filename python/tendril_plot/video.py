"""`tendril plot episode --video`: a recorded episode as a video file, its frames drawn by
tendril's software rasterizer (the tendril package's extension) and encoded by ffmpeg."""
from .episode import EpisodeError


def episode_video(args):
    try:
        import tendril
    except ImportError as error:
        raise EpisodeError(f"videos need the tendril package and its extension module ({error}): "
                           f"build it, or `pip install .`") from None
    try:
        frames = tendril.episode_video(args.episode, args.out, size=args.resolution,
                                       fps=args.fps, speed=args.speed)
    except tendril.Error as error:
        raise EpisodeError(str(error)) from None
    print(f"wrote {args.out} ({frames} frames)")
