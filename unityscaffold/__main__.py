import sys

from unityscaffold.cli import main

sys.exit(main())
