import json, sys, collections
rows=[json.loads(l) for l in open(sys.argv[1])]
by=collections.defaultdict(lambda: dict(cases=0,lines=0,fail=0,val=0,nrm=0,wit=0,flag=0,exc=0,st=collections.Counter()))
fails=[]
for r in rows:
    if 'oracle_exc' in r:
        print('ORACLE EXC', r['pid'], r['oracle_exc'][-300:]); continue
    if r.get('oracle_error'): print('ORACLE ERR', r['pid'], r['oracle_error'])
    b=by[r['cls']]; b['cases']+=1
    for e in r['ev']:
        b['lines']+=1
        b['st'][e.get('status')]+=1
        if e.get('fail'):
            b['fail']+=1; fails.append((r,e))
        b['val']=max(b['val'],e.get('val_err',0)); b['nrm']=max(b['nrm'],abs(e.get('nrm_sub',0))); b['wit']=max(b['wit'],e.get('wit',0)); b['flag']=max(b['flag'],e.get('flag_err',0))
        if 'eval_exc' in e: b['exc']+=1
print('%-8s %6s %6s %5s %9s %9s %9s %9s %s'%('class','pairs','lines','fail','val','nrm','wit','flag','status'))
for k,b in sorted(by.items()):
    print('%-8s %6d %6d %5d %9.2e %9.2e %9.2e %9.2e %s'%(k,b['cases'],b['lines'],b['fail'],b['val'],b['nrm'],b['wit'],b['flag'],dict(b['st'])))
if len(sys.argv)>2:
    c=collections.Counter()
    for r,e in fails:
        c[(r['cls'],tuple(e['fail']))]+=1
    for k,v in c.most_common(): print(v,k)
