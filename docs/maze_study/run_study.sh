P=${P:-pseudoshadow}; M=scenes/maze/maze.toml
$P maze plan --participants 12 --conditions on,off --out plan.csv
errs=(0 2 1 1 2 0); passes=(1 2 3 2 2 1)
for i in 1 2 3 4 5 6; do
  $P maze script --maze $M --plan plan.csv --participant P0$i --errors ${errs[$((i-1))]} --passes ${passes[$((i-1))]} --out P0$i.traj
done
mkdir -p study
for i in 1 2 3 4 6; do $P maze --maze $M --plan plan.csv --participant P0$i --device trajectory:P0$i.traj --out study/P0$i -q; done
# P05: paced at 8x real time, killed (SIGKILL) 2.5 s in, then resumed
$P maze --maze $M --plan plan.csv --participant P05 --device trajectory:P05.traj --out study/P05 --pace 8 -q & pid=$!
sleep 2.5; kill -9 $pid; wait $pid
$P maze --resume study/P05
$P maze summarize study/*/session.jsonl --out summary
