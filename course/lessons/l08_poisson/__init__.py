"""Lesson 08 · Poisson image editing: the chapter beside ``notebooks/08_poisson.ipynb``.

- :mod:`.lesson`: lesson 08, Poisson image editing: its registry entry, pictures, landmarks and
  printed lines;
- :mod:`.check`: lesson 08's exercises: the lab's boundary ring for the correction ``g``, and its
  sweep;
- :mod:`.apps`: lesson 08's apps: where to paste, and an iterative Poisson solve, sweep by sweep;
- :mod:`.figures`: lesson 08's still pictures: a clone that works, its correction, a clone that
  cannot keep the colours, masks and mixed gradients, inpainting, and the tiny clone solved by hand;
- :mod:`.convergence`: lesson 08's convergence: how far the lab's sweeps get, how slowly Jacobi's
  error decays, and the sweeps app's questions answered;
- :mod:`.mistakes`: the known mistakes lesson 08's checkers name, each reproduced on the checker's
  cases;
- :mod:`.sweep_picture`: the picture of a wrong sweep: when Jacobi stops and when the student's
  loop did, and where the student's ``g`` differs from Jacobi's.

The notebook imports its checkers as ``from course.lessons.l08_poisson import check``.
"""
