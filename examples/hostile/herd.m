% Hostile: a herd of its own processes that would read as a starved machine. Euler's equations
% (3.8) start, through system(... &), as many shell loops as the sandbox allows, pinned to one core
% and waking together every 0.1 s for a burst of work, then pause for ever. Judged per task (the
% task the check waits on sleeps; the tree keeps more tasks runnable than its cores), the check is
% the code's TIMEOUT ("it starves itself"), never the machine's ERROR. vee, which is correct, still
% passes.

function d = euler_3_8(I, P)
  loop = ['taskset -c 0 sh -c ''while :; do sleep 0.1; i=0; ', ...
          'while [ $i -lt 4000 ]; do i=$((i+1)); done; done'' >/dev/null 2>&1 &'];
  for k = 1:40
    system(loop);
  end
  pause(3600);
  d = cross(P, P ./ I);
end

function v = vee(m)
  v = [m(3, 2); m(1, 3); m(2, 1)];
end
