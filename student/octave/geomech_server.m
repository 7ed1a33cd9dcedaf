% geomech slot server for Octave/MATLAB-style implementations (docs/PROTOCOL.md, version 2).
%
%   octave-cli geomech_server.m mine.m        (one file of functions)
%   octave-cli geomech_server.m folder/       (one .m file per function)
%   octave-cli geomech_server.m week3.ipynb.json  (a notebook's code cells, written by the harness)
%
% Checked in double only. Vectors are passed as column vectors, matrices as matrices, the Lie
% algebra as 'so3'/'so4'/'sl2', states as structs with fields Pi and O (or M and O), the canonical
% pairs (Q, P) of the Clebsch steps as cells {Q, P}; pairs are returned as cells {a, b}.
% Replies go to the descriptor $GEOMECH_REPLY_FD (3), so the student's disp and printf (on stdout)
% can never be taken for one. A request {"session": "begin"} forks a copy of this process that
% answers one check's calls and ends at {"session": "end"}.
1;

% The kind of a C++ type in a signature: 'Mat3<T>' -> 'Mat3', 'const Vec3<T>& v' -> 'Vec3'.
function out = gm_kind(text)
  text = regexprep(text, '\<const\>', '');
  t = regexp(text, '^\s*(\w+)', 'tokens', 'once');
  out = t{1};
end

% The argument kinds of a signature 'R(const A<T>& a, int n)' -> {'A', 'int'}.
function kinds = gm_arg_kinds(sig)
  open = find(sig == '(', 1);
  inner = sig(open + 1:end - 1);
  kinds = {};
  if isempty(strtrim(inner)), return; end
  parts = strsplit(inner, ',');
  for k = 1:numel(parts)
    kinds{end + 1} = gm_kind(parts{k});
  end
end

% A signature's result kind, argument kinds, and which arguments are not pairs (decoded inline);
% `shape` says how gm_answer writes the result inline: 1 a vector, 2 a matrix, 0 by gm_encode.
function k = gm_kinds(sig)
  args = gm_arg_kinds(sig);
  result = gm_kind(sig);
  shape = 0;
  if any(strcmp(result, {'Vec3', 'Vec6', 'VecX'})), shape = 1; end
  if any(strcmp(result, {'Mat3', 'MatX'})), shape = 2; end
  k = struct('result', result, 'args', {args}, ...
             'plain', ~(strcmp(args, 'Vec3Pair') | strcmp(args, 'MatXPair')), 'shape', shape);
end

% A JSON value (after jsondecode) as Octave numbers: strings are decimal numbers ('so3' stays a
% string), arrays of rows become matrices, flat arrays column vectors. Vectorised: the interpreter's
% per-element work is what a call costs.
function v = gm_decode(j)
  if ischar(j)
    v = str2double(j);
    if isnan(v) && ~strcmpi(j, 'nan')
      v = j;            % 'so3', 'so4', 'sl2'
    end
  elseif iscell(j)
    if isempty(j)
      v = zeros(0, 1);
    elseif ischar(j{1})
      v = reshape(str2double(j), [], 1);
    elseif iscell(j{1})  % rows of strings
      cols = [j{:}];     % column r holds row r
      v = str2double(cols).';
    else
      v = zeros(numel(j), 1);
      for k = 1:numel(j)
        v(k) = double(j{k});
      end
    end
  elseif isstruct(j)
    v = struct();
    f = fieldnames(j);
    for k = 1:numel(f)
      v.(f{k}) = gm_decode(j.(f{k}));
    end
  elseif isnumeric(j)
    v = double(j);
  else
    v = j;
  end
end

% An argument of a known kind: a pair (Q, P) is a cell {Q, P}.
function v = gm_decode_kind(kind, j)
  if strcmp(kind, 'Vec3Pair') || strcmp(kind, 'MatXPair')
    if iscell(j)
      v = {gm_decode(j{1}), gm_decode(j{2})};
    else  % jsondecode made a numeric array of the two rows (Vec3Pair)
      v = {reshape(double(j(1, :)), [], 1), reshape(double(j(2, :)), [], 1)};
      if strcmp(kind, 'MatXPair')
        v = {squeeze(double(j(1, :, :))), squeeze(double(j(2, :, :)))};
      end
    end
  else
    v = gm_decode(j);
  end
end

function gm_real(x)
  if ~(isnumeric(x) || islogical(x))
    error('geomech:class', 'expected numbers, got a value of class %s', class(x));
  end
  if ~isreal(x)
    error('geomech:complex', 'a complex number where a real was expected');
  end
end

function s = gm_num(x)
  gm_real(x);
  s = sprintf('"%.17g"', double(x));
end

% The encoders run once per reply: built-in functions only (sprintf, indexing), as a call of an
% m-file function such as repmat or strjoin costs more than the formatting itself.
function s = gm_vec(x)
  gm_real(x);
  if isempty(x), s = '[]'; return; end
  s = ['[' sprintf('"%.17g",', double(x(:)))];
  s(end) = ']';
end

function s = gm_mat(x)
  gm_real(x);
  if ndims(x) > 2
    error('geomech:shape', 'expected a matrix, got an array of %d dimensions', ndims(x));
  end
  [r, c] = size(x);
  if r == 0 || c == 0, s = '[]'; return; end
  one = '"%.17g",';
  row = ['[' reshape(one(ones(1, c), :).', 1, []) ','];   % '["%.17g",...,"%.17g",,'
  row(end - 1) = ']';
  s = ['[' sprintf(row, double(x).')];
  s(end) = ']';
end

function s = gm_encode(kind, x)
  switch kind
    case 'T'
      if numel(x) ~= 1
        error('geomech:shape', 'expected a scalar, got a %dx%d array', size(x, 1), size(x, 2));
      end
      s = gm_num(x);
    case {'Vec3', 'Vec6', 'VecX'}
      s = gm_vec(x);
    case {'Mat3', 'MatX'}
      s = gm_mat(x);
    case {'Vec3Pair', 'MatXPair'}
      k = 'Vec3';
      if strcmp(kind, 'MatXPair'), k = 'MatX'; end
      if ~iscell(x) || numel(x) ~= 2
        error('geomech:shape', 'expected a pair as a cell {a, b}');
      end
      s = ['[' gm_encode(k, x{1}) ',' gm_encode(k, x{2}) ']'];
    case 'RigidBodyState'
      if iscell(x), x = struct('Pi', x{1}, 'O', x{2}); end
      s = ['{"Pi":' gm_vec(x.Pi) ',"O":' gm_mat(x.O) '}'];
    case 'ManakovState'
      if iscell(x), x = struct('M', x{1}, 'O', x{2}); end
      s = ['{"M":' gm_mat(x.M) ',"O":' gm_mat(x.O) '}'];
    otherwise
      error('geomech:kind', 'unknown result kind %s', kind);
  end
end

% A rigid-body state in its declared form (docs/PROTOCOL.md, "State forms"): keys{1} is O or q,
% keys{2} one of Pi, Omega, omega, pi; from a struct with those fields or a cell {attitude, angular}.
function s = gm_encode_declared(keys, x)
  if iscell(x) && numel(x) == 2
    a = x{1}; w = x{2};
  elseif isstruct(x) && numel(x) == 1
    if ~isfield(x, keys{1}) || ~isfield(x, keys{2})
      error('geomech:state', 'a state without the field %s or %s', keys{1}, keys{2});
    end
    a = x.(keys{1}); w = x.(keys{2});
  else
    error('geomech:state', 'expected a state as a struct with fields %s and %s, or a cell {%s, %s}', ...
          keys{1}, keys{2}, keys{1}, keys{2});
  end
  if strcmp(keys{1}, 'O'), as = gm_mat(a); else, as = gm_vec(a); end
  s = ['{"' keys{1} '":' as ',"' keys{2} '":' gm_vec(w) '}'];
end

function gm_send(out, s)
  fprintf(out, '%s\n', s);
  fflush(out);
end

% A frame's file and line as the student knows them: the sourced copy of a file (its line 1 added)
% named as the file, a notebook cell's copy as the cell ("week3.ipynb, cell 4, In [3]").
function [fl, ln] = gm_where(sources, fl, ln)
  for k = 1:numel(sources)
    if strcmp(fl, sources(k).file)
      fl = sources(k).name;
      ln = ln - sources(k).added;
      return;
    end
  end
end

% The text of a failed load: its message, the sourced copies named as the student knows them, and
% the student's frames.
function tb = gm_load_error(err, sources)
  tb = err.message;
  for k = 1:numel(sources)
    tb = strrep(tb, sources(k).file, sources(k).name);
  end
  for s = 1:numel(err.stack)
    [fl, ln] = gm_where(sources, err.stack(s).file, err.stack(s).line);
    if ~isempty(strfind(fl, 'geomech_server.m')), continue; end
    [~, stem] = fileparts(err.stack(s).file);
    if strcmp(err.stack(s).name, err.stack(s).file) || strcmp(err.stack(s).name, stem)  % a copy's own code
      tb = sprintf('%s\n    at line %d (%s)', tb, ln, fl);
    else
      tb = sprintf('%s\n    at %s, line %d (%s)', tb, err.stack(s).name, ln, fl);
    end
  end
end

% The reply to {"id", "calls": [...]}: one {"ok": value} or {"error", "traceback"} per call.
function reply = gm_answer(req, slot_kinds, integ, step_kinds, sources)
  calls = req.calls;
  results = cell(1, numel(calls));
  for c = 1:numel(calls)
    if iscell(calls), call = calls{c}; else, call = calls(c); end
    try
      a = call.args;
      if ~iscell(a), a = num2cell(a); end
      stepping = isfield(call, 'integrator') && ~isempty(call.integrator);
      if stepping
        kinds = step_kinds.(call.slot);
      else
        kinds = slot_kinds.(call.slot);
      end
      vals = cell(1, numel(a));
      for k = 1:numel(a)
        j = a{k};
        % The commonest arguments, a vector or a scalar (or 'so3'), are decoded here: a call of
        % one of the functions above costs more than the decoding.
        if ~kinds.plain(k)
          vals{k} = gm_decode_kind(kinds.args{k}, j);
        elseif iscell(j) && ~isempty(j) && ischar(j{1})
          vals{k} = reshape(str2double(j), [], 1);
        elseif iscell(j) && ~isempty(j) && iscell(j{1})   % a matrix: rows of strings, as gm_decode reads them
          cols = [j{:}];
          vals{k} = str2double(cols).';
        elseif ischar(j)
          vals{k} = str2double(j);
          if isnan(vals{k}) && ~strcmpi(j, 'nan'), vals{k} = j; end
        else
          vals{k} = gm_decode(j);
        end
      end
      declared = {};
      if stepping
        f = [];
        for q = 1:numel(integ)
          if strcmp(integ{q}.name, call.integrator)
            f = integ{q}.(call.slot);
            if strcmp(call.slot, 'rigid_body_step'), declared = integ{q}.state_keys; end
          end
        end
        if isempty(f), error('geomech:integrator', 'no integrator %s with a %s', call.integrator, call.slot); end
        if isfield(call, 'repeat')
          % A run of steps (docs/PROTOCOL.md): each step's state, encoded as its reply would be, is
          % the next step's argument, as if the harness had made the calls one by one.
          n = call.repeat;
          if ~isnumeric(n) || n < 1 || numel(vals) ~= 3
            error('geomech:repeat', '"repeat" needs an integrator''s step, its three arguments and a count of at least 1');
          end
          states = cell(1, n);
          for s = 1:n
            if isempty(declared)
              states{s} = gm_encode(kinds.result, f(vals{:}));
            else
              states{s} = gm_encode_declared(declared, f(vals{:}));
            end
            vals{2} = gm_decode_kind(kinds.args{2}, jsondecode(states{s}, 'makeValidName', false));
          end
          results{c} = [',{"ok":[' sprintf('%s,', states{:})];
          results{c}(end) = ']';
          results{c} = [results{c} '}'];
          continue;
        end
        r = f(vals{:});
      else
        r = feval(call.slot, vals{:});
      end
      % The commonest results, a vector or a matrix, are written here as gm_vec and gm_mat write
      % them: their calls (and gm_encode's, and gm_real's) cost twice the formatting itself.
      if ~isempty(declared)
        results{c} = [',{"ok":' gm_encode_declared(declared, r) '}'];
      elseif kinds.shape == 1 && isnumeric(r) && isreal(r)
        if isempty(r)
          results{c} = ',{"ok":[]}';
        else
          enc = [',{"ok":[' sprintf('"%.17g",', double(r(:)))];
          enc(end) = ']';
          results{c} = [enc '}'];
        end
      elseif kinds.shape == 2 && isnumeric(r) && isreal(r) && ndims(r) == 2 && ~isempty(r)
        one = '"%.17g",';
        row = ['[' reshape(one(ones(1, columns(r)), :).', 1, []) ','];   % '["%.17g",...,"%.17g",,'
        row(end - 1) = ']';
        enc = [',{"ok":[' sprintf(row, double(r).')];
        enc(end) = ']';
        results{c} = [enc '}'];
      else
        results{c} = [',{"ok":' gm_encode(kinds.result, r) '}'];
      end
    catch err
      tb = err.message;
      for s = 1:numel(err.stack)
        fl = err.stack(s).file; ln = err.stack(s).line;
        [fl, ln] = gm_where(sources, fl, ln);
        if ~isempty(strfind(fl, 'geomech_server.m')), continue; end
        tb = sprintf('%s\n    at %s, line %d (%s)', tb, err.stack(s).name, ln, fl);
      end
      results{c} = sprintf(',{"error":%s,"traceback":%s}', jsonencode(err.message), jsonencode(tb));
    end
  end
  joined = [results{:}];   % each result begins with its comma
  reply = sprintf('{"id":%d,"results":[%s]}', req.id, joined(2:end));
end

% $GEOMECH_PROFILE=dir: a session's time by function (Octave's profiler), written to
% dir/session-PID.txt, most costly first: seconds (its callees' included) and calls.
function gm_write_profile(where)
  profile off;
  t = profile('info').FunctionTable;
  [~, order] = sort([t.TotalTime], 'descend');
  fid = fopen(fullfile(where, sprintf('session-%d.txt', getpid())), 'w');
  fprintf(fid, '%10s %9s  %s\n', 'seconds', 'calls', 'function');
  for k = order
    fprintf(fid, '%10.3f %9d  %s\n', t(k).TotalTime, t(k).NumCalls, t(k).FunctionName);
  end
  fclose(fid);
end

% Answers requests until the input ends (0) or, in a session, until {"session": "end"} (1).
function r = gm_serve(out, in_session, slot_kinds, integ, step_kinds, sources)
  r = 0;
  while true
    line = fgetl(stdin);
    if ~ischar(line), return; end
    % The empty line after each request (a request's first character is '{': isspace is not
    % run over the whole of it).
    if isempty(line) || (line(1) ~= '{' && all(isspace(line))), continue; end
    req = jsondecode(line, 'makeValidName', false);
    if isfield(req, 'session')
      if strcmp(req.session, 'end') && in_session
        gm_send(out, sprintf('{"id":%d,"session":"ended"}', req.id));
        r = 1;
        return;
      end
      if strcmp(req.session, 'begin') && ~in_session
        [pid, msg] = fork();
        if pid == 0
          gm_send(out, sprintf('{"id":%d,"session":"begun","pid":%d}', req.id, getpid()));
          where = getenv('GEOMECH_PROFILE');
          if ~isempty(where), profile on; end
          gm_serve(out, true, slot_kinds, integ, step_kinds, sources);
          if ~isempty(where), gm_write_profile(where); end
          exit(77);   % ended by request or at the end of input; 77, so that the student's exit(0) is not taken for it
        end
        [~, status] = waitpid(pid);
        if ~(WIFEXITED(status) && WEXITSTATUS(status) == 77)
          if WIFSIGNALED(status)
            how = sprintf('was killed by signal %d', WTERMSIG(status));
          else
            how = sprintf('exited with status %d (exit() called in the implementation?)', WEXITSTATUS(status));
          end
          gm_send(out, ['{"id":null,"died":' jsonencode(how) '}']);
        end
        continue;
      end
      gm_send(out, sprintf('{"id":%d,"fatal":"unexpected session request"}', req.id));
      continue;
    end
    gm_send(out, gm_answer(req, slot_kinds, integ, step_kinds, sources));
  end
end

% ---- main -----------------------------------------------------------------------------------------
args = argv();
target = args{end};
reply_fd = getenv('GEOMECH_REPLY_FD');
if isempty(reply_fd)
  out = stdout;
else
  out = fopen(['/proc/self/fd/' reply_fd], 'w');
end
table = jsondecode(getenv('GEOMECH_SLOT_TABLE'), 'makeValidName', false);
names = {};
slot_kinds = struct();
slotlist = table.slots;
for k = 1:numel(slotlist)
  if iscell(slotlist), s = slotlist{k}; else, s = slotlist(k); end
  names{end + 1} = s.name;
  slot_kinds.(s.name) = gm_kinds(s.signature);
end
step_kinds = struct();
step_names = fieldnames(table.steps);
for k = 1:numel(step_names)
  sig = table.steps.(step_names{k});
  step_kinds.(step_names{k}) = gm_kinds(sig);
end

% What was sourced: each copy's file, the name it stands for and the lines added at its top.
sources = struct('file', {}, 'name', {}, 'added', {});
is_cells = numel(target) > 5 && strcmp(target(end - 4:end), '.json');
try
  if isfolder(target)
    addpath(target);
  elseif is_cells
    % A notebook's code cells (docs/PROTOCOL.md, "Notebooks"), run in order as its kernel runs them,
    % each from a copy of its own: a frame in it, or a parse error, names the cell.
    nb = jsondecode(fileread(target), 'makeValidName', false);
    list = nb.cells;
    if ~isempty(nb.folder), addpath(nb.folder); end
    % The cells' functions are named otherwise than their copies, which is not worth a warning.
    warning('off', 'Octave:function-name-clash');
    for k = 1:numel(list)
      if iscell(list), cell_k = list{k}; else, cell_k = list(k); end
      copy = [tempname() '.m'];
      fid = fopen(copy, 'w');
      % "1;" first, so that a cell that begins with a function defines them all; on the cell's first
      % line, so that its lines keep their numbers (but after a block comment's %{, alone on its line).
      block = ~isempty(regexp(cell_k.code, '^\s*[%#]\{', 'once'));
      if block, fprintf(fid, '1;\n%s', cell_k.code); else, fprintf(fid, '1; %s', cell_k.code); end
      fclose(fid);
      sources(end + 1) = struct('file', copy, 'name', cell_k.name, 'added', block);
      try
        __parse_file__(copy);  % a syntax error's line, which source() does not say
        source(copy);
      catch err
        delete(copy);
        gm_send(out, ['{"protocol":"geomech-slots","version":2,"language":"octave","fatal":' ...
                      jsonencode([cell_k.name ' failed when run (the cells before it ran): ' ...
                                  gm_load_error(err, sources)]) '}']);
        exit(1);
      end
      delete(copy);
    end
  else
    text = fileread(target);
    copy = [tempname() '.m'];
    fid = fopen(copy, 'w');
    fprintf(fid, '1;\n%s\n', text);
    fclose(fid);
    sources(end + 1) = struct('file', copy, 'name', target, 'added', 1);
    source(copy);
    delete(copy);
  end
catch err
  gm_send(out, ['{"protocol":"geomech-slots","version":2,"language":"octave","fatal":' ...
                jsonencode(['loading ' target ' failed: ' err.message]) '}']);
  exit(1);
end

have = {};
for k = 1:numel(names)
  n = names{k};
  e = exist(n);
  if ~(e == 2 || e == 103)
    continue;
  end
  if e == 2 && ~isfolder(target)
    continue;   % a file of that name elsewhere on the path, not the student's
  end
  have{end + 1} = n;
end

% Integrators: a function geomech_integrators() returning a struct array with fields name, claims
% (struct), optionally domain (struct: max_omega, max_pi, min_h) and function handles rigid_body_step / manakov_step / clebsch_step / manakov_clebsch_step.
integ = {};
ijson = {};
if exist('geomech_integrators') == 2 || exist('geomech_integrators') == 103
  list = geomech_integrators();
  for k = 1:numel(list)
    it = list(k);
    steps = {};
    entry = struct('name', it.name);
    for q = 1:numel(step_names)
      entry.(step_names{q}) = [];
      if isfield(it, step_names{q}) && ~isempty(it.(step_names{q}))
        steps{end + 1} = ['"' step_names{q} '"'];
        entry.(step_names{q}) = it.(step_names{q});
      end
    end
    c = '{}';
    if isfield(it, 'claims') && ~isempty(it.claims), c = jsonencode(it.claims); end
    % A declared state form ('quaternion_wxyz omega') and a stated precision with its reason.
    extra = '';
    entry.state_keys = {};
    keys = {'state', 'precision', 'precision_reason'};
    for q = 1:numel(keys)
      if isfield(it, keys{q}) && ischar(it.(keys{q})) && ~isempty(it.(keys{q}))
        extra = [extra sprintf(',"%s":%s', keys{q}, jsonencode(it.(keys{q})))];
      end
    end
    if isfield(it, 'state') && ischar(it.state) && ~isempty(it.state)
      words = strsplit(strtrim(strrep(it.state, ',', ' ')));
      words = words(~cellfun(@isempty, words));
      if numel(words) == 2
        if strcmp(words{1}, 'matrix'), entry.state_keys = {'O', words{2}}; else, entry.state_keys = {'q', words{2}}; end
      end
    end
    dom = '{}';  % where the step is meant to work
    if isfield(it, 'domain') && ~isempty(it.domain), dom = jsonencode(it.domain); end
    ijson{end + 1} = sprintf('{"name":%s,"steps":[%s],"scalars":["double"],"claims":%s,"domain":%s%s}', jsonencode(it.name), ...
                             strjoin(steps, ','), c, dom, extra);
    integ{end + 1} = entry;
  end
end

desc = 'an Octave implementation';
if exist('geomech_description') == 2 || exist('geomech_description') == 103
  desc = geomech_description();
end
quoted = cellfun(@(s) ['"' s '"'], have, 'UniformOutput', false);
% The interpreter that runs the file, for the report.
me = fullfile(OCTAVE_HOME(), 'bin', 'octave-cli');
gm_send(out, sprintf(['{"protocol":"geomech-slots","version":2,"language":"octave","language_version":%s,"interpreter":%s,' ...
                      '"description":%s,"slots":{"double":[%s]},"integrators":[%s],"notes":{},"warnings":[],' ...
                      '"sessions":true,"repeat":true}'], ...
                     jsonencode(version()), jsonencode(me), jsonencode(desc), strjoin(quoted, ','), strjoin(ijson, ',')));
gm_serve(out, false, slot_kinds, integ, step_kinds, sources);
