"""python -m strew"""

import sys

from .cli import main

sys.exit(main())
